// `linesurf arrange PLANES.json --box ...`: builds the exact cell complex of the planes inside a
// box (debug subcommand) and prints its counts as one JSON object on stdout.

#include "engine/io/reference_json.h"
#include "partition/arrangement/build_cell_complex.h"
#include "partition/arrangement/validate_cell_complex.h"
#include "partition/arrangement/write_cells_ply.h"
#include "tools/cli/commands.h"
#include "tools/cli/engine_run_context.h"
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
  Box3 box_in_world;
  box_in_world.min = Vec3(args.box[0], args.box[1], args.box[2]);
  box_in_world.max = Vec3(args.box[3], args.box[4], args.box[5]);
  if (!box_in_world.min.allFinite() || !box_in_world.max.allFinite() ||
      !(box_in_world.min.array() < box_in_world.max.array()).all()) {
    return ReportError(Error{ErrorCode::kInvalidOptions, "arrange", "--box needs XMIN < XMAX, YMIN < YMAX, ZMIN < ZMAX"});
  }
  partition::CellsPlyOptions ply_options;
  ply_options.shrink = args.shrink;
  if (auto valid = ply_options.Validate(); !valid) return ReportError(valid.error());
  OutputFiles files("arrange");
  files.AddInput(args.planes_path);
  files.AddOutput("--cells-ply", args.cells_ply, {".ply"});
  if (Status s = files.Prepare(); !s) return ReportError(s.error());
  auto scene = io::ReadReferenceJson(args.planes_path);
  if (!scene) return ReportError(scene.error());

  // The complex works in a local frame centred on the box (the box and the file share a frame).
  const Vec3 centre = box_in_world.Center();
  Box3 box;
  box.min = box_in_world.min - centre;
  box.max = box_in_world.max - centre;
  std::vector<Plane3> planes;
  planes.reserve(scene->planes.size());
  for (const Plane3& p : scene->planes) {
    Plane3 local = p;
    local.point = scene->world_from_local.Apply(p.point) - centre;
    planes.push_back(local);
  }
  RunContext ctx;
  ConfigureRunContext(common, ctx);
  auto built = partition::BuildCellComplex(box, planes, {}, ctx);
  if (!built) return ReportError(built.error());
  const CellComplex& cx = built->complex;
  const partition::CellComplexStats& s = built->stats;
  for (const std::string& w : built->warnings) PrintWarning(common, w);

  nlohmann::json out = {
      {"cells", cx.NumCells()},
      {"facets", cx.NumFacets()},
      {"edges", cx.NumEdges()},
      {"vertices", cx.NumVertices()},
      {"planes_input", s.planes_input},
      {"planes_used", s.planes_used},
      {"planes_skipped", s.planes_skipped_outside + s.planes_skipped_touching + s.planes_duplicate +
                             s.planes_invalid},
      {"planes_skipped_outside", s.planes_skipped_outside},
      {"planes_skipped_touching", s.planes_skipped_touching},
      {"planes_duplicate", s.planes_duplicate},
      {"planes_invalid", s.planes_invalid},
      {"exact_fallbacks", s.exact_fallbacks},
      {"seconds", s.seconds},
  };
  if (args.validate) {
    const Status valid = partition::ValidateCellComplex(cx);
    out["valid"] = valid.has_value();
    if (!valid) out["validation_error"] = valid.error().ToString();
  }
  if (!args.cells_ply.empty()) {
    ply_options.translation = centre;
    if (Status written = files.Write(
            args.cells_ply,
            [&](const auto& path) { return partition::WriteCellsPly(cx, path, ply_options); });
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
