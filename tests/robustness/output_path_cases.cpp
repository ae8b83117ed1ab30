// Hostile cases of kind "output path": every output path that equals an input or another
// output, has an unknown extension, or cannot be written is refused before any work (exit 2),
// for every subcommand that writes files; missing inputs are exit 3 from every subcommand; a
// full stdout is never exit 0.

#include "tests/robustness/hostile_case.h"
#include "tests/robustness/hostile_cases.h"

#include <filesystem>

namespace linesurf::robustness {
namespace fs = std::filesystem;

namespace {

void WriteInputScene(const fs::path& dir) { WriteFile(dir / "in.json", CubeSceneJson()); }

void Meshes(const fs::path& dir) {
  WriteFile(dir / "result.off", CubeOff());
  WriteFile(dir / "gt.off", CubeOff());
}

/// `in.json` plus a hard link to it under `alias` (same file, other name and extension).
HostileCase::Maker SceneWithAlias(const std::string& alias) {
  return [alias](const fs::path& dir) {
    WriteInputScene(dir);
    fs::create_hard_link(dir / "in.json", dir / alias);
  };
}

HostileCase Refused(const std::string& name,
                    HostileCase::Maker make,
                    const std::string& args,
                    std::vector<std::string> message) {
  return HostileCase{"output path", name, std::move(make), args, 2, std::move(message), {}, ""};
}

}  // namespace

std::vector<HostileCase> OutputPathCases() {
  std::vector<HostileCase> cases = {
      // Unknown output formats: refused before the input is even read (the input is broken, so
      // a late check would say exit 3).
      Refused("reconstruct_stl",
              [](const fs::path& d) { WriteFile(d / "in.json", "{"); },
              "reconstruct in.json -o out.stl",
              {"out.stl", "-o", ".stl"}),
      Refused("detect_ply",
              [](const fs::path& d) { WriteFile(d / "in.json", "{"); },
              "detect in.json -o out.ply",
              {"out.ply", "-o", ".json"}),
      Refused("detect_vg_extension",
              WriteInputScene,
              "detect in.json -o p.json --vg p.txt",
              {"p.txt", "--vg", ".vg"}),
      Refused("convert_ply", WriteInputScene, "convert in.json -o out.ply", {"out.ply", ".json"}),
      Refused("render_jpg", Meshes, "render --mesh gt.off -o out.jpg", {"out.jpg", ".png"}),
      Refused("arrange_cells_obj",
              WriteInputScene,
              "arrange in.json --box -2,-2,-2,2,2,2 --cells-ply c.obj",
              {"c.obj", "--cells-ply"}),
      // Outputs that are inputs (same path, or the same file under another name).
      Refused("reconstruct_report_is_input",
              WriteInputScene,
              "reconstruct in.json -o out.ply --report in.json",
              {"in.json", "--report", "input"}),
      Refused("reconstruct_report_is_input_via_dot",
              WriteInputScene,
              "reconstruct in.json -o out.ply --report ./in.json",
              {"in.json", "--report", "input"}),
      Refused("detect_output_is_input",
              WriteInputScene,
              "detect in.json -o in.json",
              {"in.json", "-o", "input"}),
      Refused("detect_vg_is_input",
              SceneWithAlias("in.vg"),
              "detect in.json -o p.json --vg in.vg",
              {"in.vg", "--vg", "input"}),
      Refused("detect_report_is_input",
              WriteInputScene,
              "detect in.json -o p.json --report in.json",
              {"in.json", "--report", "input"}),
      Refused("convert_output_is_input",
              WriteInputScene,
              "convert in.json -o in.json",
              {"in.json", "input"}),
      Refused("convert_output_is_input_link",
              [](const fs::path& d) {
                WriteInputScene(d);
                fs::create_symlink("in.json", d / "link.json");
              },
              "convert in.json -o link.json",
              {"link.json", "input"}),
      Refused("evaluate_json_is_gt",
              Meshes,
              "evaluate result.off gt.off --json gt.off",
              {"gt.off", "--json", "input"}),
      Refused("evaluate_json_is_result",
              Meshes,
              "evaluate result.off gt.off --json result.off",
              {"result.off", "--json", "input"}),
      Refused("render_output_is_mesh",
              [](const fs::path& d) {
                Meshes(d);
                fs::create_hard_link(d / "gt.off", d / "gt.png");
              },
              "render --mesh gt.off -o gt.png",
              {"gt.png", "input"}),
      Refused("arrange_cells_is_input",
              SceneWithAlias("in.ply"),
              "arrange in.json --box -2,-2,-2,2,2,2 --cells-ply in.ply",
              {"in.ply", "input"}),
      // Two outputs on one file.
      Refused("reconstruct_report_is_output",
              WriteInputScene,
              "reconstruct in.json -o out.ply --report out.ply",
              {"out.ply", "--report", "-o"}),
      Refused("detect_report_is_output",
              WriteInputScene,
              "detect in.json -o p.json --report p.json",
              {"p.json", "--report", "-o"}),
      // Directories that do not exist or are not directories, special files.
      Refused("reconstruct_missing_directory",
              WriteInputScene,
              "reconstruct in.json -o nowhere/out.ply",
              {"nowhere/out.ply", "does not exist"}),
      Refused("detect_report_in_missing_directory",
              WriteInputScene,
              "detect in.json -o p.json --report nowhere/r.json",
              {"nowhere/r.json", "--report"}),
      Refused("convert_output_is_directory",
              [](const fs::path& d) {
                WriteInputScene(d);
                fs::create_directory(d / "dir.json");
              },
              "convert in.json -o dir.json",
              {"dir.json", "directory"}),
      Refused("reconstruct_report_unwritable",
              WriteInputScene,
              "reconstruct in.json -o out.ply --report /proc/report.json",
              {"/proc/report.json", "--report"}),
      Refused("evaluate_json_special_file",
              Meshes,
              "evaluate result.off gt.off --json /dev/null",
              {"/dev/null", "--json", "regular file"}),
      Refused("synth_output_is_file",
              [](const fs::path& d) { WriteFile(d / "taken", "x"); },
              "synth cube -o taken",
              {"taken", "-o"}),
  };
  // Every file ends at 512 bytes (file size limit of 1 block, SIGXFSZ ignored, so a write past
  // it fails with EFBIG; the error message still fits): exit 3, and neither file nor directory
  // left, not even the directories synth made for its files.
  HostileCase unwritable{"output path",
                         "synth_writes_fail",
                         [](const fs::path&) {},
                         "synth cube -o new/s",
                         3,
                         {"new/s/lines.json"},
                         {},
                         ""};
  unwritable.before = "trap '' XFSZ; ulimit -f 1";
  cases.push_back(std::move(unwritable));
  // A missing input: exit 3 naming the file, from every subcommand that reads one.
  const std::pair<const char*, const char*> missing[] = {
      {"info", "info missing.json"},
      {"convert", "convert missing.json -o out.json"},
      {"detect", "detect missing.json -o out.json"},
      {"reconstruct", "reconstruct missing.json -o out.ply"},
      {"arrange", "arrange missing.json --box 0,0,0,1,1,1"},
      {"evaluate", "evaluate missing.off missing.off"},
      {"render", "render --mesh missing.off -o out.png"},
  };
  for (const auto& [command, args] : missing) {
    cases.push_back(HostileCase{"missing input",
                                std::string(command) + "_missing_input",
                                [](const fs::path&) {},
                                args,
                                3,
                                {"missing.", "no such file"},
                                {},
                                ""});
  }
  // A full device on stdout is an error, never exit 0.
  const std::pair<const char*, const char*> full[] = {
      {"info", "info in.json"},
      {"version", "version"},
      {"arrange", "arrange in.json --box -2,-2,-2,2,2,2"},
  };
  for (const auto& [command, args] : full) {
    cases.push_back(HostileCase{"output path",
                                std::string(command) + "_stdout_full",
                                WriteInputScene,
                                args,
                                3,
                                {"standard output"},
                                {},
                                "/dev/full"});
  }
  // Sound paths still work (and write exactly what they name).
  cases.push_back(HostileCase{"output path",
                              "detect_all_outputs",
                              WriteInputScene,
                              "detect in.json -o p.json --vg p.vg --report r.json",
                              0,
                              {},
                              {"p.json", "p.vg", "r.json"},
                              ""});
  cases.push_back(HostileCase{"output path",
                              "reconstruct_into_subdirectory",
                              [](const fs::path& d) {
                                WriteInputScene(d);
                                fs::create_directory(d / "sub");
                              },
                              "reconstruct in.json -o sub/out.ply --report sub/r.json",
                              0,
                              {},
                              {"sub/out.ply", "sub/r.json"},
                              ""});
  cases.push_back(HostileCase{"output path",
                              "evaluate_json_stdout",
                              Meshes,
                              "evaluate result.off gt.off --json -",
                              0,
                              {},
                              {},
                              ""});
  return cases;
}

}  // namespace linesurf::robustness
