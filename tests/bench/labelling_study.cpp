// The integral labelling against the integer optimum (docs/user/results.md, "Integral labelling"),
// printed as Markdown tables. Every row solves one energy several ways: the LP bound (Clp), the
// labels right after rounding, after local search, after the default improvement, and the
// integer optimum by Cbc (branch and cut; "stopped" when it does not prove optimality within
// the time limit, then its best bound is shown).
//   linesurf_labelling_study grids [sizes=6,8,10,12] [cbc_seconds=600]
//       solver::testing::GridEnergy n^3 (every term kind, default weights).
//   linesurf_labelling_study scenes [cbc_seconds=600]
//       synth cube, house, room, city-1 (seed 1, 1 cm noise, 5 % outliers), given planes,
//       default options: the energy the pipeline builds.
//   linesurf_labelling_study andalusian PATH XMIN,YMIN,ZMIN,XMAX,YMAX,ZMAX [cbc_seconds=600]
//       the Andalusian segments with both ends in the box (world frame), the given planes that
//       keep a member, reference weights (textural 1, structural 1, visibility 1, edge 0.1,
//       corner 0.1, sigma 1): the full LP (pdhg) and the band strategy, each with the
//       labelling of rounding and local search alone and with the default, then Cbc.

#include "engine/io/read_scene.h"
#include "engine/pipeline/reconstruct.h"
#include "solver/lp/lp_backend.h"
#include "tests/bench/crop_scene.h"
#include "tests/support/random_energy.h"
#include "tools/gen/synthesize.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

namespace linesurf {
namespace {

// One way to solve: what the row reports from it.
struct Outcome {
  double objective = 0.0;
  double rounded = 0.0;
  double relaxed = 0.0;
  double lower_bound = 0.0;
  std::string lower_bound_source;
  std::string method;
  std::string status;
  std::string backend;
  std::size_t cells = 0;
  std::size_t lp_columns = 0;
  std::size_t full_cells = 0;
  std::size_t windows = 0;
  double seconds = 0.0;
};

using Solve = std::function<Outcome(const solver::LabelingOptions&)>;

// Default options with the improvement steps after local search switched on or off.
solver::LabelingOptions Options(SolverBackend backend, bool group_moves, bool windows) {
  solver::LabelingOptions o;
  o.backend = backend;
  if (!group_moves) o.improve.group_move_passes = 0;
  if (!windows) o.improve.window_cells = 0;
  return o;
}

double GapPercent(double value, double optimum) {
  return 100.0 * (value - optimum) / std::max(std::abs(optimum), 1e-12);
}

void PrintHeader() {
  std::printf(
      "| energy | cells | LP columns | LP bound | rounded | + local search | + group moves | "
      "+ exact windows | integer optimum (Cbc) | gap rounded | gap local search | gap group "
      "moves | gap windows | windows | labelling s | Cbc s |\n"
      "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
}

// Clp's LP with and without group moves (local search on), then Cbc.
void PrintRow(const std::string& name, const Solve& solve, double cbc_seconds) {
  const Outcome lp = solve(Options(SolverBackend::kClp, false, false));
  const Outcome grouped = solve(Options(SolverBackend::kClp, true, false));
  const Outcome windowed = solve(Options(SolverBackend::kClp, true, true));
  solver::LabelingOptions cbc_options = Options(SolverBackend::kCbc, false, false);
  cbc_options.time_limit_seconds = cbc_seconds;
  const Outcome ilp = solve(cbc_options);
  const bool proven = ilp.status == "optimal";
  std::ostringstream optimum;
  optimum.precision(6);
  if (proven) {
    optimum << ilp.objective;
  } else {
    optimum << ilp.objective << " (" << ilp.status << ", bound " << ilp.lower_bound << ")";
  }
  std::printf(
      "| %s | %zu | %zu | %.6g | %.6g | %.6g | %.6g | %.6g | %s | %.2f %% | %.2f %% | "
      "%.2f %% | %.2f %% | %zu | %.1f | %.1f |\n",
      name.c_str(),
      lp.cells,
      lp.lp_columns,
      lp.relaxed,
      lp.rounded,
      lp.objective,
      grouped.objective,
      windowed.objective,
      optimum.str().c_str(),
      GapPercent(lp.rounded, ilp.objective),
      GapPercent(lp.objective, ilp.objective),
      GapPercent(grouped.objective, ilp.objective),
      GapPercent(windowed.objective, ilp.objective),
      windowed.windows,
      windowed.seconds,
      ilp.seconds);
  std::fflush(stdout);
}

Outcome FromLabeling(const solver::LabelingResult& r, std::size_t cells) {
  Outcome o;
  o.objective = r.labels_objective;
  o.rounded = r.rounded_objective;
  o.relaxed = r.relaxed_objective;
  o.lower_bound = r.lower_bound;
  o.lower_bound_source = r.lower_bound_source;
  o.method = r.method;
  o.status = r.status;
  o.backend = solver::BackendReportName(r);
  o.cells = cells;
  o.lp_columns = r.lp_columns;
  o.seconds = r.seconds;
  o.windows = r.windows;
  for (std::uint8_t l : r.labels) o.full_cells += l;
  return o;
}

Outcome FromStats(const pipeline::RunStats& s) {
  Outcome o;
  o.objective = s.labeling.objective;
  o.rounded = s.labeling.rounded_objective;
  o.relaxed = s.labeling.relaxed_objective;
  o.lower_bound = s.labeling.lower_bound;
  o.lower_bound_source = s.labeling.lower_bound_source;
  o.method = s.labeling.labeling_method;
  o.status = s.labeling.solver_status;
  o.backend = s.labeling.solver_backend;
  o.cells = s.complex.cells;
  o.lp_columns = s.labeling.lp_variables;
  o.full_cells = s.labeling.full_cells;
  for (const auto& [stage, seconds] : s.resources.stage_seconds) {
    if (stage == "solve") o.seconds = seconds;
  }
  return o;
}

[[noreturn]] void Fail(const Error& e) {
  std::fprintf(stderr, "labelling_study: %s\n", e.ToString().c_str());
  std::exit(1);
}

Solve EnergySolve(const solver::EnergyInput& energy) {
  return [&energy](const solver::LabelingOptions& options) {
    auto r = solver::SolveLabeling(energy, options, RunContext{});
    if (!r) Fail(r.error());
    return FromLabeling(*r, energy.NumCells());
  };
}

Solve SceneSolve(const Scene& scene, const pipeline::ReconstructOptions& base) {
  return [&scene, base](const solver::LabelingOptions& options) {
    pipeline::ReconstructOptions o = base;
    o.solver = options;
    auto r = pipeline::Reconstruct(scene, o, RunContext{});
    if (!r) Fail(r.error());
    return FromStats(r->stats);
  };
}

std::vector<double> ParseList(const char* text) {
  std::vector<double> out;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) out.push_back(std::stod(item));
  return out;
}

int Grids(const std::vector<double>& sizes, double cbc_seconds) {
  PrintHeader();
  for (double n : sizes) {
    solver::testing::GridEnergySpec spec;
    spec.nx = spec.ny = spec.nz = static_cast<int>(n);
    const solver::EnergyInput energy = solver::testing::GridEnergy(spec);
    PrintRow("grid " + std::to_string(spec.nx) + "^3", EnergySolve(energy), cbc_seconds);
  }
  return 0;
}

int Scenes(double cbc_seconds) {
  PrintHeader();
  struct Case {
    const char* family;
    int size;
  };
  for (const Case c : {Case{"cube", 0}, Case{"house", 0}, Case{"room", 0}, Case{"city", 1}}) {
    synth::SynthSpec spec;
    spec.family = c.family;
    spec.size = c.size;
    spec.seed = 1;
    spec.noise_sigma = 0.01;
    spec.outlier_fraction = 0.05;
    auto s = synth::Synthesize(spec);
    if (!s) Fail(s.error());
    pipeline::ReconstructOptions o;
    o.use_given_planes = true;
    std::ostringstream name;
    name << c.family;
    if (c.size > 0) name << '-' << c.size;
    PrintRow(name.str(), SceneSolve(s->scene, o), cbc_seconds);
  }
  return 0;
}

int Andalusian(const char* path, const char* box, double cbc_seconds) {
  auto scene = io::ReadScene(path, {});
  if (!scene) Fail(scene.error());
  const std::vector<double> b = ParseList(box);
  if (b.size() != 6) {
    std::fprintf(stderr, "labelling_study: the box needs 6 numbers\n");
    return 2;
  }
  const Scene crop = bench::CropScene(*scene, Vec3(b[0], b[1], b[2]), Vec3(b[3], b[4], b[5]));
  pipeline::ReconstructOptions o;
  o.use_given_planes = true;
  o.scene_mode = pipeline::SceneMode::kExterior;
  o.energy.weights.textural = 1.0;
  o.energy.weights.structural = 1.0;
  o.energy.weights.visibility = 1.0;
  o.energy.weights.edge = 0.1;
  o.energy.weights.corner = 0.1;
  o.energy.sigma = 1.0;
  std::printf("crop: %zu segments, %zu planes\n\n", crop.NumSegments(), crop.planes.size());
  std::fflush(stdout);
  const Solve solve = SceneSolve(crop, o);
  std::printf(
      "| solve | method | cells | LP columns | objective | full cells | lower bound (source) | "
      "solve s |\n|---|---|---|---|---|---|---|---|\n");
  for (const SolverBackend backend : {SolverBackend::kPdhg, SolverBackend::kBand}) {
    for (const bool improve : {false, true}) {
      const Outcome r = solve(Options(backend, improve, improve));
      std::printf("| %s%s | %s | %zu | %zu | %.6g | %zu | %.6g (%s) | %.1f |\n",
                  SolverBackendName(backend),
                  improve ? "" : " (rounding and local search only)",
                  r.method.c_str(),
                  r.cells,
                  r.lp_columns,
                  r.objective,
                  r.full_cells,
                  r.lower_bound,
                  r.lower_bound_source.c_str(),
                  r.seconds);
      std::fflush(stdout);
    }
  }
  solver::LabelingOptions cbc_options = Options(SolverBackend::kCbc, false, false);
  cbc_options.time_limit_seconds = cbc_seconds;
  const Outcome ilp = solve(cbc_options);
  std::printf("| cbc | %s | %zu | %zu | %.6g (%s) | %zu | %.6g (%s) | %.1f |\n",
              ilp.method.c_str(),
              ilp.cells,
              ilp.lp_columns,
              ilp.objective,
              ilp.status.c_str(),
              ilp.full_cells,
              ilp.lower_bound,
              ilp.lower_bound_source.c_str(),
              ilp.seconds);
  return 0;
}

}  // namespace
}  // namespace linesurf

int main(int argc, char** argv) {
  using namespace linesurf;
  const std::string mode = argc > 1 ? argv[1] : "";
  if (mode == "grids") {
    return Grids(ParseList(argc > 2 ? argv[2] : "6,8,10,12"), argc > 3 ? std::atof(argv[3]) : 600);
  }
  if (mode == "scenes") return Scenes(argc > 2 ? std::atof(argv[2]) : 600);
  if (mode == "andalusian" && argc > 3) {
    return Andalusian(argv[2], argv[3], argc > 4 ? std::atof(argv[4]) : 600);
  }
  std::fprintf(stderr,
               "usage: linesurf_labelling_study grids [sizes] [cbc_seconds] | scenes "
               "[cbc_seconds] | andalusian PATH XMIN,YMIN,ZMIN,XMAX,YMAX,ZMAX [cbc_seconds]\n");
  return 2;
}
