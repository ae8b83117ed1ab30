#include "engine/pipeline/detection_work_units.h"

#include <chrono>
#include <cstdio>
#include <exception>
#include <optional>
#include <utility>

#include <nlohmann/json.hpp>

#include "engine/core/exception.h"
#include "engine/io/file_access.h"
#include "engine/pipeline/stage_timer.h"

namespace linesurf::pipeline {
namespace {

using Json = nlohmann::json;

constexpr const char* kWorkUnitsStage = "work_units";
constexpr const char* kManifestFormat = "linesurf-work-directory-1";
constexpr const char* kUnitFormat = "linesurf-work-unit-1";

std::string HashOf(std::string_view bytes) {
  std::uint64_t h = 0xcbf29ce484222325ULL;  // FNV-1a 64
  for (const char c : bytes) {
    h ^= static_cast<unsigned char>(c);
    h *= 0x100000001b3ULL;
  }
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(h));
  return text;
}

std::string UnitId(const partition::BlockKey& key) {
  return "detect-L" + std::to_string(key.level) + "-" + std::to_string(key.index.x()) + "_" +
         std::to_string(key.index.y()) + "_" + std::to_string(key.index.z());
}

std::filesystem::path InputPath(const std::filesystem::path& dir, const std::string& id) {
  return dir / "units" / (id + ".input.json");
}

std::filesystem::path ResultPath(const std::filesystem::path& dir, const std::string& id) {
  return dir / "units" / (id + ".result.json");
}

Json Vec3Json(const Vec3& v) { return Json::array({v.x(), v.y(), v.z()}); }

Vec3 Vec3Of(const Json& j) {
  return {j.at(0).get<double>(), j.at(1).get<double>(), j.at(2).get<double>()};
}

/// The input of one run: what RunDetectionBlock reads, and the run's options.
std::string UnitInputText(const std::string& id,
                          std::span<const Segment3> lines,
                          const detect::DetectionRunRequest& request,
                          double epsilon,
                          const std::string& options_json) {
  Json segments = Json::array();
  for (const SegmentId s : request.block->segments) {
    const Segment3& l = lines[s.index()];
    segments.push_back(Json::array({l.p1.x(), l.p1.y(), l.p1.z(), l.p2.x(), l.p2.y(), l.p2.z()}));
  }
  const partition::BlockKey& key = request.block->key;
  Json j = {{"format", kUnitFormat},
            {"unit", id},
            {"stage", "detect"},
            {"block", {{"level", key.level},
                       {"index", Json::array({key.index.x(), key.index.y(), key.index.z()})}}},
            {"run", request.run},
            {"seed", request.seed},
            {"may_split", request.may_split},
            {"report_progress", request.report_progress},
            {"epsilon", epsilon},
            {"options", Json::parse(options_json)},
            {"segments", std::move(segments)}};
  return j.dump() + "\n";
}

/// The result file of a unit whose input hashed to `hash`, or nothing when there is none for that
/// input (none yet, another input's, or unreadable: the unit runs again).
std::optional<Json> ReadResult(const std::filesystem::path& path, const std::string& hash) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) return std::nullopt;
  try {
    Json j = Json::parse(io::ReadWholeFile(path, kWorkUnitsStage));
    if (j.value("input_hash", std::string()) != hash) return std::nullopt;
    return j;
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

detect::DetectionRunOutcome OutcomeOf(const Json& result) {
  detect::DetectionRunOutcome outcome;
  if (result.at("status").get<std::string>() != "done") return outcome;
  outcome.candidates_evaluated = result.at("candidates_evaluated").get<std::int64_t>();
  outcome.failed_draws = result.at("failed_draws").get<std::int64_t>();
  outcome.capped = result.at("capped").get<bool>();
  outcome.split = result.at("split").get<bool>();
  for (const Json& p : result.at("planes")) {
    detect::SupportedPlane& plane = outcome.planes.emplace_back();
    plane.plane.point = Vec3Of(p.at("point"));
    plane.plane.normal = Vec3Of(p.at("normal"));
    for (const Json& s : p.at("inliers")) plane.inliers.emplace_back(s.get<std::size_t>());
  }
  return outcome;
}

Json ResultJson(const std::string& id,
                const std::string& hash,
                const detect::DetectionRunOutcome& outcome,
                double seconds) {
  Json planes = Json::array();
  for (const detect::SupportedPlane& p : outcome.planes) {
    Json inliers = Json::array();
    for (const SegmentId s : p.inliers) inliers.push_back(s.index());
    planes.push_back({{"point", Vec3Json(p.plane.point)},
                      {"normal", Vec3Json(p.plane.normal)},
                      {"inliers", std::move(inliers)}});
  }
  return {{"format", kUnitFormat},
          {"unit", id},
          {"status", "done"},
          {"input_hash", hash},
          {"candidates_evaluated", outcome.candidates_evaluated},
          {"failed_draws", outcome.failed_draws},
          {"capped", outcome.capped},
          {"split", outcome.split},
          {"seconds", seconds},
          {"peak_rss_bytes", PeakRssBytes()},
          {"planes", std::move(planes)}};
}

/// The manifest's entry of unit `id` in `work_dir`; throws kInvalidInput naming what is missing.
Json ManifestEntry(const std::filesystem::path& work_dir, const std::string& id) {
  const std::filesystem::path path = work_dir / "manifest.json";
  Json manifest;
  try {
    manifest = Json::parse(io::ReadWholeFile(path, kWorkUnitsStage));
  } catch (const Json::exception& e) {
    ThrowError(ErrorCode::kInvalidInput, kWorkUnitsStage, path.string() + ": " + e.what());
  }
  for (const Json& unit : manifest.value("units", Json::array())) {
    if (unit.value("id", std::string()) == id) return unit;
  }
  ThrowError(ErrorCode::kInvalidInput, kWorkUnitsStage,
             path.string() + ": no work unit '" + id + "'");
}

}  // namespace

const char* WorkUnitStatusName(WorkUnitStatus status) {
  switch (status) {
    case WorkUnitStatus::kPending: return "pending";
    case WorkUnitStatus::kDone: return "done";
    case WorkUnitStatus::kFailed: return "failed";
  }
  return "pending";
}

DetectionWorkUnits::DetectionWorkUnits(std::filesystem::path work_dir, std::string options_json)
    : work_dir_(std::move(work_dir)), options_json_(std::move(options_json)) {}

std::vector<detect::DetectionRunOutcome> DetectionWorkUnits::RunRound(
    std::span<const Segment3> lines,
    std::span<const detect::DetectionRunRequest> round,
    const PlaneDetectionOptions& /*options: the units read the run's own*/,
    double epsilon,
    const RunContext& ctx) {
  std::error_code ec;
  std::filesystem::create_directories(work_dir_ / "units", ec);
  LINESURF_THROW_IF(ec, kInvalidInput, kWorkUnitsStage,
                    "work directory " << work_dir_.string() << ": " << ec.message());
  std::vector<detect::DetectionRunOutcome> outcomes(round.size());
  bool pending = false;
  for (std::size_t i = 0; i < round.size(); ++i) {
    ctx.ThrowIfCancelled(kWorkUnitsStage);
    WorkUnitEntry& unit = units_.emplace_back();
    unit.id = UnitId(round[i].block->key);
    unit.stage = "detect";
    const std::string input = UnitInputText(unit.id, lines, round[i], epsilon, options_json_);
    unit.input_hash = HashOf(input);
    if (const std::optional<Json> result = ReadResult(ResultPath(work_dir_, unit.id),
                                                      unit.input_hash)) {
      ++reused_;
      outcomes[i] = OutcomeOf(*result);
      const bool done = result->at("status").get<std::string>() == "done";
      unit.status = done ? WorkUnitStatus::kDone : WorkUnitStatus::kFailed;
      unit.reason = result->value("reason", std::string());
      unit.seconds = result->value("seconds", 0.0);
      continue;
    }
    pending = true;
    io::WriteFileAtomically(InputPath(work_dir_, unit.id), input, kWorkUnitsStage);
  }
  if (pending) {
    WriteManifest();
    ThrowError(ErrorCode::kCancelled, kWorkUnitsStage,
               std::to_string(Pending().size()) + " work units pending in " + work_dir_.string());
  }
  return outcomes;
}

std::vector<std::string> DetectionWorkUnits::Pending() const {
  std::vector<std::string> ids;
  for (const WorkUnitEntry& u : units_) {
    if (u.status == WorkUnitStatus::kPending) ids.push_back(u.id);
  }
  return ids;
}

void DetectionWorkUnits::WriteManifest() const {
  Json units = Json::array();
  for (const WorkUnitEntry& u : units_) {
    units.push_back({{"id", u.id},
                     {"stage", u.stage},
                     {"status", WorkUnitStatusName(u.status)},
                     {"input", "units/" + u.id + ".input.json"},
                     {"result", "units/" + u.id + ".result.json"},
                     {"input_hash", u.input_hash},
                     {"reason", u.reason},
                     {"seconds", u.seconds}});
  }
  const Json manifest = {{"format", kManifestFormat},
                         {"pending", Pending().size()},
                         {"units", std::move(units)}};
  io::WriteFileAtomically(work_dir_ / "manifest.json", manifest.dump(1) + "\n", kWorkUnitsStage);
}

WorkUnitEntry RunDetectionUnit(const std::filesystem::path& work_dir,
                               const std::string& id,
                               DetectionOptionsReader read_options,
                               const RunContext& ctx) {
  const Json entry = ManifestEntry(work_dir, id);
  WorkUnitEntry unit;
  unit.id = id;
  unit.stage = "detect";
  unit.input_hash = entry.value("input_hash", std::string());
  const std::filesystem::path input_path = InputPath(work_dir, id);
  const auto start = std::chrono::steady_clock::now();
  Json result;
  try {
    const std::string input = io::ReadWholeFile(input_path, kWorkUnitsStage);
    if (const std::string hash = HashOf(input); hash != unit.input_hash) {
      ThrowError(ErrorCode::kInvalidInput, kWorkUnitsStage,
                 input_path.string() + ": not the input planned for the unit (hash " + hash +
                     ", planned " + unit.input_hash + ")");
    }
    Json j;
    try {
      j = Json::parse(input);
    } catch (const Json::exception& e) {
      ThrowError(ErrorCode::kInvalidInput, kWorkUnitsStage, input_path.string() + ": " + e.what());
    }
    std::vector<Segment3> lines;
    for (const Json& s : j.at("segments")) {
      Segment3& l = lines.emplace_back();
      l.p1 = Vec3(s.at(0).get<double>(), s.at(1).get<double>(), s.at(2).get<double>());
      l.p2 = Vec3(s.at(3).get<double>(), s.at(4).get<double>(), s.at(5).get<double>());
    }
    const detect::DetectionRunRequest request{
        .block = nullptr,
        .run = j.at("run").get<std::size_t>(),
        .seed = j.at("seed").get<std::uint64_t>(),
        .may_split = j.at("may_split").get<bool>(),
        .report_progress = j.at("report_progress").get<bool>()};
    const detect::DetectionRunOutcome outcome = detect::RunDetectionBlock(
        lines, request, read_options(j.at("options").dump()), j.at("epsilon").get<double>(), ctx);
    unit.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    unit.status = WorkUnitStatus::kDone;
    result = ResultJson(id, unit.input_hash, outcome, unit.seconds);
  } catch (const LinesurfException& e) {
    if (e.error().code != ErrorCode::kInvalidInput) throw;
    unit.status = WorkUnitStatus::kFailed;
    unit.reason = e.error().message;
  } catch (const Json::exception& e) {
    unit.status = WorkUnitStatus::kFailed;
    unit.reason = input_path.string() + ": " + e.what();
  }
  if (unit.status == WorkUnitStatus::kFailed) {
    result = {{"format", kUnitFormat},
              {"unit", id},
              {"status", "failed"},
              {"input_hash", unit.input_hash},
              {"reason", unit.reason}};
  }
  io::WriteFileAtomically(ResultPath(work_dir, id), result.dump() + "\n", kWorkUnitsStage);
  return unit;
}

}  // namespace linesurf::pipeline
