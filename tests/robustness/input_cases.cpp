// Hostile cases of kinds "malformed file", "degenerate geometry" and "extreme coordinates": every
// reader (reference JSON, Line3D++ + NVM, OBJ lines, PLY/OBJ/OFF meshes) through every
// subcommand that reads it.

#include "tests/robustness/hostile_case.h"
#include "tests/robustness/hostile_cases.h"

#include <cstdio>
#include <string>

namespace linesurf::robustness {
namespace fs = std::filesystem;

namespace {

/// A scene input: its file name, its content and the words its error must contain.
struct BadScene {
  BadScene(std::string name_in,
           std::string file_in,
           std::string content_in,
           std::vector<std::string> place_in,
           int exit_code_in = 3,
           std::string extra_args_in = "",
           std::vector<std::pair<std::string, std::string>> extra_files_in = {})
      : name(std::move(name_in)),
        file(std::move(file_in)),
        content(std::move(content_in)),
        place(std::move(place_in)),
        exit_code(exit_code_in),
        extra_args(std::move(extra_args_in)),
        extra_files(std::move(extra_files_in)) {}
  std::string name;
  std::string file;
  std::string content;
  std::vector<std::string> place;
  int exit_code = 3;
  std::string extra_args;  // e.g. --nvm for Line3D++
  std::vector<std::pair<std::string, std::string>> extra_files;
};

std::string OneLine(const std::string& pt1, const std::string& pt2, const std::string& views) {
  return R"({"lines": [{"pt1": )" + pt1 + R"(, "pt2": )" + pt2 + R"(, "pt_views": )" + views +
         "}]}\n";
}

/// The cube scene moved by `offset` (georeferenced-like) or scaled by `scale`.
std::string CubeTransformed(double scale, double offset) {
  std::string json = CubeSceneJson();
  std::string out;
  // Rewrite every number of the form [-]d(.d*) inside brackets: numbers are the only digits.
  for (std::size_t i = 0; i < json.size();) {
    const bool after_letter =  // the digit of a key such as "pt1"
        i > 0 && std::isalpha(static_cast<unsigned char>(json[i - 1])) != 0;
    const bool starts_number =
        !after_letter && ((std::isdigit(static_cast<unsigned char>(json[i])) != 0) ||
                          (json[i] == '-' && i + 1 < json.size() &&
                           std::isdigit(static_cast<unsigned char>(json[i + 1])) != 0));
    if (!starts_number) {
      out += json[i++];
      continue;
    }
    std::size_t used = 0;
    const double v = std::stod(json.substr(i), &used);
    char text[64];
    std::snprintf(text, sizeof(text), "%.17g", v * scale + offset);
    out += text;
    i += used;
  }
  return out;
}

std::vector<BadScene> BadScenes() {
  const std::string views = "[[0, 5, 0]]";
  const std::string two_views = "[[0, 5, 0], [1, 5, 0]]";
  return {
      {"json_truncated", "in.json", R"({"lines": [{"pt1": [0, 0, 0], )", {"in.json"}},
      {"json_empty", "in.json", "", {"in.json", "empty file"}},
      {"json_binary_garbage", "in.json", std::string("\x89PNG\r\n\x1a\n\0\0\0", 11), {"in.json"}},
      {"json_lines_not_array", "in.json", R"({"lines": 5})", {"in.json", "lines"}},
      {"json_pt1_two_numbers",
       "in.json",
       OneLine("[0, 0]", "[1, 0, 0]", views),
       {"in.json", "lines[0].pt1"}},
      {"json_pt2_string",
       "in.json",
       OneLine("[0, 0, 0]", R"("far")", views),
       {"in.json", "lines[0].pt2"}},
      {"json_views_not_array",
       "in.json",
       OneLine("[0, 0, 0]", "[1, 0, 0]", "7"),
       {"in.json", "lines[0].pt_views"}},
      {"json_number_overflow",
       "in.json",
       OneLine("[0, 0, 1e400]", "[1, 0, 0]", views),
       {"in.json", "lines[0]"}},
      {"json_nan_literal", "in.json", OneLine("[0, NaN, 0]", "[1, 0, 0]", views), {"in.json"}},
      {"json_plane_index_not_array",
       "in.json",
       R"({"lines": [{"pt1": [0, 0, 0], "pt2": [1, 0, 0], "pt_views": )" + two_views +
           R"(, "plane_index": "x"}]})",
       {"in.json", "lines[0].plane_index"}},
      {"json_top_level_array", "in.json", "[1, 2, 3]", {"in.json"}},
      {"unknown_extension", "in.csv", "0 0 0 1 1 1\n", {"in.csv", "unknown input format"}, 2},
      {"line3dpp_bad_number",
       "in.txt",
       "1 0 0 0 x 1 1 1 0\n",
       {"in.txt", "line 1"},
       3,
       "--nvm m.nvm",
       {{"m.nvm", "NVM_V3\n\n1\na.jpg 500 1 0 0 0 0 0 5 0 0\n\n0\n"}}},
      {"line3dpp_camera_out_of_range",
       "in.txt",
       "1 0 0 0 1 1 1 1 7 0 0 1 1\n",
       {"in.txt", "line 1"},
       3,
       "--nvm m.nvm",
       {{"m.nvm", "NVM_V3\n\n1\na.jpg 500 1 0 0 0 0 0 5 0 0\n\n0\n"}}},
      {"nvm_truncated",
       "in.txt",
       "1 0 0 0 1 1 1 0\n",
       {"m.nvm"},
       3,
       "--nvm m.nvm",
       {{"m.nvm", "NVM_V3\n\n2\na.jpg 500 1 0 0 0 0 0 5 0 0\n"}}},
      {"line3dpp_without_cameras", "in.txt", "1 0 0 0 1 1 1 0\n", {"in.txt", "--nvm"}, 2},
      {"obj_index_out_of_range", "in.obj", "v 0 0 0\nv 1 0 0\nl 1 5\n", {"in.obj", "line 3"}},
      {"obj_vertex_two_numbers", "in.obj", "v 0 0\nv 1 0 0\nl 1 2\n", {"in.obj", "line 1"}},
      {"input_is_directory", "in.json", "", {"in.json", "directory"}},
  };
}

/// Degenerate scenes: valid files from which nothing (or only a warning) comes out.
std::vector<BadScene> DegenerateScenes() {
  const std::string views = "[[0, 5, 0], [1, 5, 0]]";
  std::string zero_length = R"({"lines": [)";
  for (int i = 0; i < 5; ++i) {
    zero_length += std::string(i ? "," : "") +
                   R"({"pt1": [1, 2, 3], "pt2": [1, 2, 3], "pt_views": )" + views + "}";
  }
  zero_length += "]}";
  return {
      {"no_segments", "in.json", R"({"lines": []})", {"in.json", "no usable segment"}},
      {"zero_length_segments", "in.json", zero_length, {"in.json", "no usable segment"}},
      {"beyond_coordinate_bound",
       "in.json",
       OneLine("[0, 0, 1e13]", "[1, 0, 1e13]", views),
       {"in.json", "no usable segment", "e+12"}},
  };
}

HostileCase SceneCase(const std::string& kind,
                      const BadScene& scene,
                      const std::string& command,
                      const std::string& args) {
  HostileCase c;
  c.kind = kind;
  c.name = command + "_" + scene.name;
  c.make = [scene](const fs::path& dir) {
    if (scene.name == "input_is_directory") {
      fs::create_directory(dir / scene.file);
    } else {
      WriteFile(dir / scene.file, scene.content);
    }
    for (const auto& [name, content] : scene.extra_files) WriteFile(dir / name, content);
  };
  c.args = command + " " + scene.file + (scene.extra_args.empty() ? "" : " " + scene.extra_args) +
           (args.empty() ? "" : " " + args);
  c.exit_code = scene.exit_code;
  c.message = scene.place;
  return c;
}

/// The subcommands that read a scene, with the arguments that make them write something.
const std::pair<const char*, const char*> kSceneCommands[] = {
    {"info", ""},
    {"convert", "-o out.json"},
    {"detect", "-o out.json"},
    {"reconstruct", "-o out.ply"},
};

std::vector<HostileCase> MeshCases() {
  std::vector<HostileCase> cases;
  struct BadMesh {
    std::string name, file, content;
    std::vector<std::string> place;
  };
  const std::vector<BadMesh> meshes = {
      {"off_bad_counts", "m.off", "OFF\nx y z\n", {"m.off", "line 2"}},
      {"off_truncated", "m.off", "OFF\n8 6 0\n0 0 0\n", {"m.off", "vertex 1"}},
      {"off_face_index_out_of_range",
       "m.off",
       "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 9\n",
       {"m.off", "9"}},
      {"ply_bad_header",
       "m.ply",
       "ply\nformat ascii 1.0\nelement vertex x\nend_header\n",
       {"m.ply"}},
      {"ply_binary_truncated",
       "m.ply",
       "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float "
       "y\nproperty float z\nend_header\n\x01\x02",
       {"m.ply", "vertex"}},
      {"obj_nan_vertex", "m.obj", "v 0 0 nan\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", {"m.obj", "line 1"}},
      {"obj_face_of_two", "m.obj", "v 0 0 0\nv 1 0 0\nf 1 2\n", {"m.obj", "line 3"}},
      {"mesh_unknown_extension", "m.stl", "solid x\n", {"m.stl", "extension"}},
      // Degenerate geometry: no face with any area.
      {"all_faces_collinear",
       "m.off",
       "OFF\n3 1 0\n0 0 0\n1 0 0\n2 0 0\n3 0 1 2\n",
       {"m.off", "no face with positive area"}},
      {"no_faces",
       "m.off",
       "OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n",
       {"m.off", "no face with positive area"}},
      // Extreme coordinates: beyond the bound the readers refuse the mesh, naming the vertex.
      {"cube_1e120", "m.off", CubeOff(1e120), {"m.off", "vertex 1", "1e+120"}},
      {"cube_1e80", "m.off", CubeOff(1e80), {"m.off", "vertex 1", "1e+80"}},
      {"cube_1e13", "m.off", CubeOff(1e13), {"m.off", "vertex 1", "1e+13"}},
  };
  for (const BadMesh& m : meshes) {
    const std::string kind = m.name.rfind("cube_", 0) == 0 ? "extreme coordinates"
                             : m.name == "all_faces_collinear" || m.name == "no_faces"
                                 ? "degenerate geometry"
                                 : "malformed file";
    const auto make = [m](const fs::path& dir) {
      WriteFile(dir / m.file, m.content);
      WriteFile(dir / "gt.off", CubeOff());
    };
    cases.push_back({kind,
                     "evaluate_result_" + m.name,
                     make,
                     "evaluate " + m.file + " gt.off",
                     3,
                     m.place,
                     {},
                     ""});
    cases.push_back({kind,
                     "evaluate_gt_" + m.name,
                     make,
                     "evaluate gt.off " + m.file + " --json e.json",
                     3,
                     m.place,
                     {},
                     ""});
    // A picture of a mesh without area is a picture: only malformed files are refused.
    const bool degenerate = kind == "degenerate geometry";
    cases.push_back({kind,
                     "render_" + m.name,
                     make,
                     "render --mesh " + m.file + " -o r.png",
                     degenerate ? 0 : 3,
                     degenerate ? std::vector<std::string>{} : m.place,
                     degenerate ? std::vector<std::string>{"r.png"} : std::vector<std::string>{},
                     ""});
  }
  // Large but bounded coordinates still evaluate.
  const auto big = [](const fs::path& dir) {
    WriteFile(dir / "m.off", CubeOff(1e11));
    WriteFile(dir / "gt.off", CubeOff(1e11));
  };
  cases.push_back({"extreme coordinates",
                   "evaluate_cube_1e11",
                   big,
                   "evaluate m.off gt.off --samples 1000 --json e.json",
                   0,
                   {},
                   {"e.json"},
                   ""});
  return cases;
}

}  // namespace

std::vector<HostileCase> InputCases() {
  std::vector<HostileCase> cases;
  for (const auto& [command, args] : kSceneCommands) {
    for (const BadScene& s : BadScenes()) {
      cases.push_back(SceneCase("malformed file", s, command, args));
    }
    for (const BadScene& s : DegenerateScenes()) {
      if (std::string(command) == "convert") continue;  // convert keeps values as read
      cases.push_back(SceneCase("degenerate geometry", s, command, args));
    }
  }
  // reconstruct: valid input from which no plane comes is a failed reconstruction (exit 4).
  const auto one_segment = [](const fs::path& dir) {
    WriteFile(dir / "in.json", OneLine("[0, 0, 0]", "[1, 0, 0]", "[[0, 5, 0], [1, 5, 0]]"));
  };
  cases.push_back({"degenerate geometry",
                   "reconstruct_one_segment_no_plane",
                   one_segment,
                   "reconstruct in.json -o out.ply",
                   4,
                   {"in.json", "no plane"},
                   {},
                   ""});
  cases.push_back({"degenerate geometry",
                   "reconstruct_given_planes_none",
                   one_segment,
                   "reconstruct in.json -o out.ply --planes given",
                   3,
                   {"in.json", "no planes"},
                   {},
                   ""});
  // The cube repeated 20 times: duplicates are harmless.
  cases.push_back({"degenerate geometry",
                   "detect_massive_duplicates",
                   [](const fs::path& dir) {
                     std::string json = CubeSceneJson();
                     const std::string lines =
                         json.substr(json.find('[') + 1, json.rfind(']') - json.find('[') - 1);
                     std::string all = "{\"lines\": [" + lines;
                     for (int i = 0; i < 19; ++i) all += "," + lines;
                     WriteFile(dir / "in.json", all + "]}\n");
                   },
                   "detect in.json -o out.json",
                   0,
                   {},
                   {"out.json"},
                   ""});
  // Georeferenced offsets reconstruct like the origin.
  for (const double offset : {1e6, 1e9}) {
    char name[64];
    std::snprintf(name, sizeof(name), "reconstruct_cube_offset_%.0e", offset);
    std::string id = name;
    for (char& ch : id) {
      if (ch == '+' || ch == '.') ch = '_';
    }
    cases.push_back({"extreme coordinates",
                     id,
                     [offset](const fs::path& dir) {
                       WriteFile(dir / "in.json", CubeTransformed(1.0, offset));
                     },
                     "reconstruct in.json -o out.ply --scene exterior",
                     0,
                     {},
                     {"out.ply"},
                     ""});
  }
  cases.push_back(
      {"extreme coordinates",
       "reconstruct_cube_1e_6_scale",
       [](const fs::path& dir) { WriteFile(dir / "in.json", CubeTransformed(1e-6, 0.0)); },
       "reconstruct in.json -o out.ply --scene exterior --relative-epsilon 0.01",
       0,
       {},
       {"out.ply"},
       ""});
  for (HostileCase& c : MeshCases()) cases.push_back(std::move(c));
  return cases;
}

}  // namespace linesurf::robustness
