// `linesurf arrange PLANES.json --box ...`: builds the exact cell complex of the planes inside a
// box (debug subcommand) and prints its counts as one JSON object on stdout.

#include "linesurf/linesurf.h"

#include "tools/arrange/plane_arrangement.h"
#include "tools/cli/cli_support.h"
#include "tools/cli/commands.h"
#include "tools/cli/output_files.h"

#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace linesurf::cli {
namespace {

struct ArrangeArgs {
  std::string planes_path;
  std::vector<double> box;
  std::string cells_ply;
  double shrink = 0.8;
  bool validate = false;
};

int Run(const ArrangeArgs& args, const CommonOptions& common) {
  const Vector3 box_min{args.box[0], args.box[1], args.box[2]};
  const Vector3 box_max{args.box[3], args.box[4], args.box[5]};
  if (!arrange::IsBox(box_min, box_max)) {
    return ReportError(Error{ErrorCode::kInvalidOptions, "arrange",
                             "--box needs XMIN < XMAX, YMIN < YMAX, ZMIN < ZMAX"});
  }
  if (Status valid = arrange::ValidateCellsShrink(args.shrink); !valid) {
    return ReportError(valid.error());
  }
  OutputFiles files("arrange");
  files.AddInput(args.planes_path);
  files.AddOutput("--cells-ply", args.cells_ply, {".ply"});
  if (Status s = files.Prepare(); !s) return ReportError(s.error());
  Expected<ReadSceneResult> read = ReadScene(args.planes_path);
  if (!read) return ReportError(read.error());

  Expected<arrange::PlaneArrangement> built = arrange::PlaneArrangement::Build(
      box_min, box_max, read->scene.planes, CliRunControl(common));
  if (!built) return ReportError(built.error());
  for (const std::string& w : built->Warnings()) PrintWarning(common, w);
  const arrange::ArrangementCounts& n = built->Counts();
  nlohmann::json out = {
      {"cells", n.cells},
      {"facets", n.facets},
      {"edges", n.edges},
      {"vertices", n.vertices},
      {"planes_input", n.planes_input},
      {"planes_used", n.planes_used},
      {"planes_skipped", n.planes_skipped_outside + n.planes_skipped_touching +
                             n.planes_duplicate + n.planes_invalid},
      {"planes_skipped_outside", n.planes_skipped_outside},
      {"planes_skipped_touching", n.planes_skipped_touching},
      {"planes_duplicate", n.planes_duplicate},
      {"planes_invalid", n.planes_invalid},
      {"exact_fallbacks", n.exact_fallbacks},
      {"seconds", n.seconds},
  };
  if (args.validate) {
    const Status valid = built->Validate();
    out["valid"] = valid.has_value();
    if (!valid) out["validation_error"] = valid.error().ToString();
  }
  if (!args.cells_ply.empty()) {
    if (Status written = files.Write(
            args.cells_ply,
            [&](const auto& path) { return built->WriteCellsPly(path, args.shrink); });
        !written) {
      return ReportError(written.error());
    }
  }
  if (Status s = files.Commit(); !s) return ReportError(s.error());
  std::cout << out.dump() << "\n";
  if (args.validate && !out["valid"].get<bool>()) return kExitInternal;
  return kExitOk;
}

}  // namespace

Command AddArrangeCommand(CLI::App& app, CommonOptions& common) {
  auto args = std::make_shared<ArrangeArgs>();
  Command cmd;
  cmd.app = app.add_subcommand(
      "arrange",
      "Debug: split a box by the planes of a reference JSON file (exact cell complex) and print "
      "its counts as JSON");
  cmd.app->add_option("PLANES", args->planes_path, "Reference JSON with `planes` (lines optional)")
      ->required();
  cmd.app->add_option("--box", args->box, "XMIN,YMIN,ZMIN,XMAX,YMAX,ZMAX in the file's frame")
      ->required()
      ->delimiter(',')
      ->expected(6);
  cmd.app->add_option("--cells-ply", args->cells_ply, "Write the cells, shrunk, as binary PLY");
  cmd.app->add_option("--shrink", args->shrink, "Shrink factor of --cells-ply cells, in (0, 1]")
      ->capture_default_str();
  cmd.app->add_flag("--validate", args->validate, "Check every invariant of the complex (slow)");
  cmd.run = [args, &common] { return Run(*args, common); };
  return cmd;
}

}  // namespace linesurf::cli
