// Hostile cases of kinds "absurd option" and "thread count": values out of range, non-finite,
// negative for unsigned options, or whose derived values (weights / sigma) overflow, for every
// subcommand; thread counts below, at and far above the core count.

#include "tests/robustness/hostile_case.h"
#include "tests/robustness/hostile_cases.h"

#include <string>

namespace linesurf::robustness {
namespace fs = std::filesystem;

namespace {

void Inputs(const fs::path& dir) {
  WriteFile(dir / "in.json", CubeSceneJson());
  WriteFile(dir / "m.off", CubeOff());
}

struct AbsurdOption {
  std::string name;
  std::string args;
  std::vector<std::string> message;  // the option, and the bound or the value
};

}  // namespace

std::vector<HostileCase> OptionCases() {
  const std::vector<AbsurdOption> options = {
      {"reconstruct_sigma_1e_9", "reconstruct in.json -o out.ply --sigma 1e-9", {"sigma", "1e-09"}},
      {"reconstruct_sigma_negative", "reconstruct in.json -o out.ply --sigma -1", {"sigma"}},
      {"reconstruct_sigma_inf",
       "reconstruct in.json -o out.ply --sigma inf",
       {"--sigma", "finite"}},
      {"reconstruct_w_edge_1e308",
       "reconstruct in.json -o out.ply --w-edge 1e308",
       {"--w-edge", "weights.edge", "[0, 1e+06]"}},
      {"reconstruct_w_edge_nan",
       "reconstruct in.json -o out.ply --w-edge nan",
       {"--w-edge", "finite"}},
      {"reconstruct_w_visibility_negative",
       "reconstruct in.json -o out.ply --w-visibility -1",
       {"--w-visibility", "weights.visibility"}},
      {"reconstruct_seed_negative", "reconstruct in.json -o out.ply --seed -1", {"--seed", ">= 0"}},
      {"reconstruct_seed_text", "reconstruct in.json -o out.ply --seed abc", {"--seed"}},
      {"reconstruct_box_margin_zero",
       "reconstruct in.json -o out.ply --box-margin 0",
       {"box_margin"}},
      {"reconstruct_samples_per_sigma_huge",
       "reconstruct in.json -o out.ply --samples-per-sigma 1e9",
       {"samples_per_sigma"}},
      {"reconstruct_time_limit_negative",
       "reconstruct in.json -o out.ply --time-limit -5",
       {"--time-limit", "solver.time_limit_seconds"}},
      {"reconstruct_solver_unknown",
       "reconstruct in.json -o out.ply --solver simplex9",
       {"simplex9"}},
      {"reconstruct_scene_unknown", "reconstruct in.json -o out.ply --scene outside", {"--scene"}},
      {"detect_epsilon_zero", "detect in.json -o out.json --epsilon 0", {"--epsilon", "> 0"}},
      {"detect_epsilon_inf", "detect in.json -o out.json --epsilon inf", {"--epsilon", "finite"}},
      {"detect_relative_epsilon_huge",
       "detect in.json -o out.json --relative-epsilon 7",
       {"--relative-epsilon", "detection.relative_epsilon"}},
      {"detect_max_planes_zero", "detect in.json -o out.json --max-planes 0", {"--max-planes"}},
      {"detect_iterations_negative",
       "detect in.json -o out.json --iterations -3",
       {"--iterations"}},
      {"detect_min_support_one", "detect in.json -o out.json --min-support 1", {"--min-support", "detection.min_support", ">= 2"}},
      {"detect_block_halo_half",
       "detect in.json -o out.json --detect-block-size 1 --detect-block-halo 0.5",
       {"--detect-block-halo", "detection.block_halo"}},
      {"detect_seed_negative", "detect in.json -o out.json --seed -1", {"--seed", ">= 0"}},
      {"evaluate_samples_negative", "evaluate m.off m.off --samples -5", {"--samples", ">= 0"}},
      {"evaluate_samples_zero", "evaluate m.off m.off --samples 0", {"samples_per_mesh"}},
      {"evaluate_samples_huge",
       "evaluate m.off m.off --samples 100000000000",
       {"samples_per_mesh"}},
      {"evaluate_thresholds_decreasing",
       "evaluate m.off m.off --thresholds 0.1,0.05",
       {"increasing"}},
      {"evaluate_seed_negative", "evaluate m.off m.off --seed -2", {"--seed"}},
      {"synth_noise_1e308", "synth cube --noise 1e308 -o s", {"--noise", "[0, 10]"}},
      {"synth_seed_negative", "synth cube --seed -1 -o s", {"--seed"}},
      {"synth_size_negative", "synth city --size -4 -o s", {"--size"}},
      {"arrange_box_inverted", "arrange in.json --box 1,1,1,0,0,0", {"--box"}},
      {"arrange_box_five_numbers", "arrange in.json --box 0,0,0,1,1", {"--box"}},
      {"arrange_shrink_five", "arrange in.json --box -2,-2,-2,2,2,2 --shrink 5", {"shrink"}},
      {"render_size_zero", "render --mesh m.off -o r.png --size 0x0", {"size 0x0"}},
      {"render_size_text", "render --mesh m.off -o r.png --size big", {"--size"}},
      {"render_supersample_100", "render --mesh m.off -o r.png --supersample 100", {"supersample"}},
      {"unknown_flag", "detect in.json -o out.json --frobnicate", {"--frobnicate"}},
      {"unknown_subcommand", "reconstrukt in.json", {"reconstrukt"}},
  };
  std::vector<HostileCase> cases;
  for (const AbsurdOption& o : options) {
    cases.push_back({"absurd option", o.name, Inputs, o.args, 2, o.message, {}, ""});
  }
  // Thread counts: any count from 1 to far above the two CI cores gives a result; what is not a
  // count is refused.
  for (const int threads : {1, 2, 3, 8, 64}) {
    cases.push_back({"thread count",
                     "detect_threads_" + std::to_string(threads),
                     Inputs,
                     "-j " + std::to_string(threads) + " detect in.json -o out.json",
                     0,
                     {},
                     {"out.json"},
                     ""});
  }
  cases.push_back({"thread count",
                   "reconstruct_threads_8",
                   Inputs,
                   "-j 8 reconstruct in.json -o out.ply --scene exterior",
                   0,
                   {},
                   {"out.ply"},
                   ""});
  cases.push_back({"thread count",
                   "threads_negative",
                   Inputs,
                   "-j -1 detect in.json -o out.json",
                   2,
                   {"--threads"},
                   {},
                   ""});
  cases.push_back({"thread count",
                   "threads_too_many",
                   Inputs,
                   "-j 100000 detect in.json -o out.json",
                   2,
                   {"--threads", "[0, 256]"},
                   {},
                   ""});
  return cases;
}

}  // namespace linesurf::robustness
