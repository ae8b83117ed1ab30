// The per-block labelling ("blocks", solver/lp/block_labeling.h) against the global solve
// (docs/user/benchmarks.md, "Studies of one stage"). Prints Markdown rows.
//   linesurf_block_labelling_study grids SIZES EDGES [global=clp] [threads=2] [inner=auto]
//       solver::testing::GridEnergy n^3 for each n of SIZES, cut into cubes of each edge of
//       EDGES (comma lists); the global solve with the backend `global` (clp, pdhg, none).
//   linesurf_block_labelling_study scene PATH given|detected|crop:BOX MAX_CELLS [global=none]
//                                  [threads=2] [sweeps=2] [inner=auto] [KEY=VALUE,...]
//       the energy that `reconstruct` builds with default options (given or detected planes;
//       crop:XMIN,YMIN,ZMIN,XMAX,YMAX,ZMAX = the segments in that box, given planes and the
//       reference weights, as linesurf_labelling_study andalusian)
//       on the monolithic complex, its cells cut into k-d blocks of at most each of MAX_CELLS
//       cells (pipeline::CentroidBlocks); then the global solve with `global` (auto, pdhg,
//       none).
//   linesurf_block_labelling_study engine PATH given|detected BLOCK_SIZE MARGIN THREADS
//                                  [VARIANT;VARIANT...]
//       the energy of `reconstruct --engine blocks` (block size, 0 = automatic, and support
//       margin given; every other option at its default), solved once per variant
//       BACKEND[:KEY=VALUE,...] with the engine's blocks as the partition
//       (docs/design/lp_backend.md, "Energy pdhg").
// `inner` is BlocksOptions::backend; KEY=VALUE sets other LabelingOptions fields: window_cells,
// block_halo, local_search_passes, group_move_passes (improve.*, blocks.halo), pdhg_tolerance
// (pdhg.tolerance), pdhg_energy_tolerance (pdhg_energy.tolerance), auto_clp_max_columns,
// auto_blocks_min_columns (auto_rule.*), block_bound_passes, block_sweeps (blocks.*).

#include "engine/io/read_scene.h"
#include "engine/pipeline/block_evidence.h"
#include "tests/bench/centroid_blocks.h"
#include "engine/pipeline/decide_scene_mode.h"
#include "engine/pipeline/detect_scene_planes.h"
#include "engine/pipeline/reconstruct.h"
#include "engine/pipeline/scene_box.h"
#include "tests/support/one_complex_evidence.h"
#include "solver/lp/lp_backend.h"
#include "tests/bench/crop_scene.h"
#include "tests/support/random_energy.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <sys/resource.h>

namespace linesurf {
namespace {

[[noreturn]] void Fail(const Error& e) {
  std::fprintf(stderr, "block_labelling_study: %s\n", e.ToString().c_str());
  std::exit(1);
}

template <typename T>
T Take(Expected<T>&& e) {
  if (!e) Fail(e.error());
  return std::move(e.value());
}

std::vector<double> ParseList(const char* text) {
  std::vector<double> out;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) out.push_back(std::stod(item));
  return out;
}

// The backend named `name` (SolverBackendName's names).
SolverBackend Backend(const std::string& name) {
  const std::optional<SolverBackend> backend = SolverBackendFromName(name);
  if (!backend) {
    Fail(Error{ErrorCode::kInvalidOptions, "block_labelling_study", "no backend '" + name + "'"});
  }
  return *backend;
}

double Seconds(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

struct Row {
  std::string energy;
  std::string partition;
  solver::LabelingResult result;
  double seconds = 0.0;
  double cpu_seconds = 0.0;
};

/// User + system CPU seconds of the process so far (all threads).
double CpuSeconds() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
         1e-6 * static_cast<double>(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
}

void PrintHeader() {
  std::printf(
      "| energy | partition | method | blocks | crossing terms | block solves (LP-free) "
      "| largest block LP | sweeps | labels' energy | lower bound | gap | full cells | wall s | "
      "CPU s |\n"
      "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
}

void Print(const Row& row) {
  const solver::LabelingResult& r = row.result;
  std::size_t full = 0;
  for (std::uint8_t l : r.labels) full += l;
  const double gap =
      100.0 * (r.labels_objective - r.lower_bound) / std::max(std::abs(r.labels_objective), 1e-12);
  std::printf(
      "| %s | %s | %s | %zu | %zu | %zu (%zu) | %zu | %zu | %.4f | %.4f (%s) | "
      "%.2f %% | %zu | %.1f | %.1f |\n",
      row.energy.c_str(),
      row.partition.c_str(),
      solver::BackendReportName(r).c_str(),
      r.blocks,
      r.crossing_terms,
      r.block_solves,
      r.block_certified,
      r.block_max_lp_columns,
      r.block_sweeps,
      r.labels_objective,
      r.lower_bound,
      r.lower_bound_source.c_str(),
      gap,
      full,
      row.seconds,
      row.cpu_seconds);
  std::fflush(stdout);
}

// Progress of the solves on stderr.
class StderrLog : public LogSink {
 public:
  void Write(LogLevel, const std::string& stage, const std::string& message) noexcept override {
    std::fprintf(stderr, "[%s] %s\n", stage.c_str(), message.c_str());
  }
};

Row Run(const std::string& name,
        const std::string& partition,
        const solver::EnergyInput& energy,
        std::span<const std::uint32_t> blocks,
        const solver::LabelingOptions& options,
        int threads) {
  StderrLog log;
  RunContext ctx;
  ctx.num_threads = threads;
  ctx.log = &log;
  const auto start = std::chrono::steady_clock::now();
  const double cpu_start = CpuSeconds();
  Row row{name, partition, Take(solver::SolveLabeling(energy, blocks, options, ctx)), 0.0, 0.0};
  row.seconds = Seconds(start);
  row.cpu_seconds = CpuSeconds() - cpu_start;
  return row;
}

int Grids(const char* sizes,
          const char* edges,
          const std::string& global,
          int threads,
          const std::string& inner) {
  PrintHeader();
  for (double n : ParseList(sizes)) {
    solver::testing::GridEnergySpec spec;
    spec.nx = spec.ny = spec.nz = static_cast<int>(n);
    const solver::EnergyInput energy = solver::testing::GridEnergy(spec);
    const std::string name = "grid " + std::to_string(spec.nx) + "^3";
    solver::LabelingOptions options;
    options.backend = SolverBackend::kBlocks;
    options.blocks.backend = Backend(inner);
    for (double edge : ParseList(edges)) {
      const auto blocks = solver::testing::GridBlocks(spec, static_cast<int>(edge));
      const std::string partition = "cubes of " + std::to_string(static_cast<int>(edge)) + "^3";
      Print(Run(name, partition, energy, blocks, options, threads));
    }
    if (global != "none") {
      options.backend = Backend(global);
      Print(Run(name, "none", energy, {}, options, threads));
    }
  }
  return 0;
}

// "window_cells=0,block_halo=2" into `options`; false on an unknown key.
bool SetOptions(const std::string& list, solver::LabelingOptions& options) {
  std::stringstream in(list);
  std::string item;
  while (std::getline(in, item, ',')) {
    const std::size_t eq = item.find('=');
    if (eq == std::string::npos) return false;
    const std::string key = item.substr(0, eq);
    const double value = std::stod(item.substr(eq + 1));
    if (key == "window_cells") {
      options.improve.window_cells = static_cast<std::size_t>(value);
    } else if (key == "block_halo") {
      options.blocks.halo = static_cast<int>(value);
    } else if (key == "local_search_passes") {
      options.improve.local_search_passes = static_cast<int>(value);
    } else if (key == "group_move_passes") {
      options.improve.group_move_passes = static_cast<int>(value);
    } else if (key == "pdhg_tolerance") {
      options.pdhg.tolerance = value;
    } else if (key == "pdhg_energy_tolerance") {
      options.pdhg_energy.tolerance = value;
    } else if (key == "auto_clp_max_columns") {
      options.auto_rule.clp_max_columns = static_cast<std::size_t>(value);
    } else if (key == "block_bound_passes") {
      options.blocks.bound_passes = static_cast<int>(value);
    } else if (key == "block_sweeps") {
      options.blocks.sweeps = static_cast<int>(value);
    } else if (key == "auto_blocks_min_columns") {
      options.auto_rule.blocks_min_columns = static_cast<std::size_t>(value);
    } else {
      return false;
    }
  }
  return true;
}

int SceneStudy(const char* path,
               const std::string& planes,
               const char* max_cells,
               const std::string& global,
               int threads,
               int sweeps,
               const std::string& inner,
               const std::string& extra) {
  solver::LabelingOptions options;
  if (!SetOptions(extra, options)) {
    std::fprintf(stderr, "block_labelling_study: bad options '%s'\n", extra.c_str());
    return 2;
  }
  const auto start = std::chrono::steady_clock::now();
  Scene input = Take(io::ReadScene(path, {}));
  pipeline::ReconstructOptions o;
  RunContext ctx;
  ctx.num_threads = threads;
  Scene scene;
  if (planes.rfind("crop:", 0) == 0) {
    // The crop of docs/user/results.md, "Integral labelling": given planes, reference weights.
    const std::vector<double> b = ParseList(planes.c_str() + 5);
    if (b.size() != 6) {
      std::fprintf(stderr, "block_labelling_study: crop: needs 6 numbers\n");
      return 2;
    }
    input = bench::CropScene(input, Vec3(b[0], b[1], b[2]), Vec3(b[3], b[4], b[5]));
    o.energy.weights.textural = o.energy.weights.structural = o.energy.weights.visibility = 1.0;
    o.energy.weights.edge = o.energy.weights.corner = 0.1;
    o.energy.sigma = 1.0;
    scene = Take(pipeline::SanitizeScene(std::move(input), o.sanitize)).scene;
  } else if (planes == "given") {
    scene = Take(pipeline::SanitizeScene(std::move(input), o.sanitize)).scene;
  } else {
    scene =
        Take(pipeline::SanitizeAndDetectPlanes(std::move(input), o.sanitize, o.planes, ctx)).scene;
  }
  const double detect_seconds = Seconds(start);
  const Box3 box = pipeline::SceneBox(scene, o.box_margin);
  const auto complex_start = std::chrono::steady_clock::now();
  const partition::CellComplexResult built =
      Take(partition::BuildCellComplex(box, scene.planes.raw(), o.complex, ctx));
  const double complex_seconds = Seconds(complex_start);
  const auto evidence_start = std::chrono::steady_clock::now();
  const bool interior = pipeline::DecideSceneMode(scene).interior;
  const pipeline::EvidenceResult evidence = Take(pipeline::testing::ComputeOneComplexEvidence(
      built.complex,
      scene,
      o.energy,
      interior ? pipeline::BoundaryMode::kInterior : pipeline::BoundaryMode::kExterior,
      ctx));
  const double evidence_seconds = Seconds(evidence_start);
  const std::string name = std::string("Andalusian, ") + planes;
  std::printf(
      "%s: %zu planes, %zu cells, %zu pairs, %zu structural, %zu parity, %s; "
      "sanitize+detect %.1f s, complex %.1f s, evidence %.1f s, threads %d\n\n",
      name.c_str(),
      scene.planes.size(),
      built.complex.NumCells(),
      evidence.energy.NumPairs(),
      evidence.energy.NumStructuralGroups(),
      evidence.energy.NumParityGroups(),
      interior ? "interior" : "exterior",
      detect_seconds,
      complex_seconds,
      evidence_seconds,
      threads);
  std::fflush(stdout);
  PrintHeader();
  options.backend = SolverBackend::kBlocks;
  options.blocks.sweeps = sweeps;
  options.blocks.backend = Backend(inner);
  for (double m : ParseList(max_cells)) {
    const auto partition_start = std::chrono::steady_clock::now();
    const std::vector<std::uint32_t> blocks =
        pipeline::CentroidBlocks(built.complex, static_cast<std::size_t>(m));
    const double partition_seconds = Seconds(partition_start);
    Row row = Run(name,
                  "k-d, <= " + std::to_string(static_cast<int>(m)) + " cells",
                  evidence.energy,
                  blocks,
                  options,
                  threads);
    row.partition += " (" + std::to_string(partition_seconds).substr(0, 4) + " s)";
    Print(row);
  }
  if (global != "none") {
    options.backend = Backend(global);
    Print(Run(name, "none", evidence.energy, {}, options, threads));
  }
  return 0;
}

// The energy `reconstruct` builds (given or detected planes, default options but
// the block size and margin), solved once per variant "BACKEND[:KEY=VALUE,...]" of `variants`
// (';'-separated), with the engine's blocks as the partition.
int EngineStudy(const char* path,
                const std::string& planes,
                double block_size,
                double margin,
                int threads,
                const std::string& variants) {
  const auto start = std::chrono::steady_clock::now();
  const Scene input = Take(io::ReadScene(path, {}));
  pipeline::ReconstructOptions o;
  o.blocks.block_size = block_size;
  o.blocks.support.margin_blocks = margin;
  o.use_given_planes = planes == "given";
  o.num_threads = threads;
  RunContext ctx;
  ctx.num_threads = threads;
  const pipeline::PreparedReconstruction prepared =
      Take(pipeline::PrepareReconstruction(input, o, ctx));
  const double prepare_seconds = Seconds(start);
  const auto evidence_start = std::chrono::steady_clock::now();
  const pipeline::EvidenceResult evidence = Take(pipeline::ComputeBlockEvidence(
      prepared.blocks.complexes,
      prepared.scene,
      o.energy,
      prepared.facts.interior ? pipeline::BoundaryMode::kInterior
                              : pipeline::BoundaryMode::kExterior,
      ctx));
  const double evidence_seconds = Seconds(evidence_start);
  const std::vector<std::uint32_t> blocks =
      partition::BlockOfEachCell(prepared.blocks.complexes);
  const std::string name = "engine " + planes;
  std::printf(
      "%s: %zu planes, block size %.3f, margin %g, %zu blocks, %zu cells, %zu pairs, %zu "
      "structural, %zu parity; prepare %.1f s, evidence %.1f s, threads %d\n\n",
      name.c_str(),
      prepared.scene.planes.size(),
      prepared.stats.complex.block_size,
      margin,
      prepared.blocks.complexes.blocks.size(),
      evidence.energy.NumCells(),
      evidence.energy.NumPairs(),
      evidence.energy.NumStructuralGroups(),
      evidence.energy.NumParityGroups(),
      prepare_seconds,
      evidence_seconds,
      threads);
  std::fflush(stdout);
  PrintHeader();
  std::stringstream in(variants);
  std::string variant;
  while (std::getline(in, variant, ';')) {
    solver::LabelingOptions options;
    const std::size_t colon = variant.find(':');
    options.backend = Backend(variant.substr(0, colon));
    if (colon != std::string::npos && !SetOptions(variant.substr(colon + 1), options)) {
      std::fprintf(stderr, "block_labelling_study: bad variant '%s'\n", variant.c_str());
      return 2;
    }
    Print(Run(name, variant, evidence.energy, blocks, options, threads));
  }
  return 0;
}

}  // namespace
}  // namespace linesurf

int main(int argc, char** argv) {
  const std::string mode = argc > 1 ? argv[1] : "";
  const auto arg = [&](int i, const char* fallback) { return argc > i ? argv[i] : fallback; };
  if (mode == "grids" && argc >= 4) {
    return linesurf::Grids(argv[2], argv[3], arg(4, "clp"), std::atoi(arg(5, "2")), arg(6, "auto"));
  }
  if (mode == "scene" && argc >= 5) {
    return linesurf::SceneStudy(argv[2],
                                argv[3],
                                argv[4],
                                arg(5, "none"),
                                std::atoi(arg(6, "2")),
                                std::atoi(arg(7, "2")),
                                arg(8, "auto"),
                                arg(9, ""));
  }
  if (mode == "engine" && argc >= 7) {
    return linesurf::EngineStudy(argv[2],
                                 argv[3],
                                 std::atof(argv[4]),
                                 std::atof(argv[5]),
                                 std::atoi(argv[6]),
                                 arg(7, "auto"));
  }
  std::fprintf(
      stderr,
      "usage: linesurf_block_labelling_study grids SIZES EDGES [global] [threads] [inner] | "
      "scene PATH given|detected MAX_CELLS [global] [threads] [sweeps] [inner] [KEY=VALUE,...]\n");
  return 2;
}
