#include "tests/robustness/fuzz/fuzz_targets.h"

#include "engine/core/exception.h"
#include "engine/io/camera_centres.h"
#include "engine/io/limap_reader.h"
#include "engine/io/line3dpp_reader.h"
#include "engine/io/mesh_io.h"
#include "engine/io/obj_lines_reader.h"
#include "engine/io/reference_json.h"

#include <array>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

namespace linesurf::fuzz {
namespace {

/// A directory of this process for the input files (the readers take paths), removed at exit.
class ScratchDirectory {
 public:
  ScratchDirectory() {
    std::string pattern =
        (std::filesystem::temp_directory_path() / "linesurf-fuzz-XXXXXX").string();
    if (mkdtemp(pattern.data()) == nullptr) {
      std::perror("linesurf fuzz: mkdtemp");
      std::abort();
    }
    path_ = pattern;
  }
  ~ScratchDirectory() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  ScratchDirectory(const ScratchDirectory&) = delete;
  ScratchDirectory& operator=(const ScratchDirectory&) = delete;
  [[nodiscard]] const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

const std::filesystem::path& ScratchDir() {
  static const ScratchDirectory dir;
  return dir.path();
}

std::filesystem::path WriteInput(const std::uint8_t* data, std::size_t size, const char* name) {
  const std::filesystem::path path = ScratchDir() / name;
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  out.close();
  if (!out) {
    std::fprintf(stderr, "linesurf fuzz: cannot write %s\n", path.c_str());
    std::abort();
  }
  return path;
}

/// A finding: the reader did not turn bad input into a clear error.
[[noreturn]] void Finding(const Error& e) {
  std::fprintf(stderr,
               "linesurf fuzz: finding: %s error: %s\n",
               ErrorCodeName(e.code),
               e.ToString().c_str());
  std::abort();
}

template <typename T>
int Check(const Expected<T>& result) {
  if (!result && result.error().code == ErrorCode::kInternal) Finding(result.error());
  return 0;
}

/// Readers that throw: CatchAll turns every exception into an Error (foreign ones into
/// kInternal, which is a finding).
template <typename Fn>
int CheckThrowing(Fn&& fn) {
  return Check(CatchAll("fuzz", [&] {
    fn();
    return 0;
  }));
}

int ReferenceJson(const std::uint8_t* data, std::size_t size) {
  return Check(io::ReadReferenceJsonWithWarnings(WriteInput(data, size, "lines.json")));
}

/// Camera ids 0..7 for the track readers (other ids in the input are errors to report).
io::CameraCentres SomeCentres() {
  io::CameraCentres centres;
  for (std::int64_t id = 0; id < 8; ++id) centres[id] = Vec3(static_cast<double>(id), 0.0, 1.0);
  return centres;
}

int Line3dpp(const std::uint8_t* data, std::size_t size) {
  const io::CameraCentres centres = SomeCentres();
  const std::filesystem::path path = WriteInput(data, size, "lines.txt");
  return CheckThrowing([&] { (void)io::ReadLine3dpp(path, centres); });
}

int Nvm(const std::uint8_t* data, std::size_t size) {
  const std::filesystem::path path = WriteInput(data, size, "model.nvm");
  return CheckThrowing([&] { (void)io::ReadNvmCameraCentres(path); });
}

int Colmap(const std::uint8_t* data, std::size_t size) {
  const std::filesystem::path path = WriteInput(data, size, "images.txt");
  return CheckThrowing([&] { (void)io::ReadColmapCameraCentres(path); });
}

int ColmapBinary(const std::uint8_t* data, std::size_t size) {
  const std::filesystem::path path = WriteInput(data, size, "images.bin");
  return CheckThrowing([&] { (void)io::ReadColmapCameraCentres(path); });
}

int Limap(const std::uint8_t* data, std::size_t size) {
  const io::CameraCentres centres = SomeCentres();
  const std::filesystem::path path = WriteInput(data, size, "alltracks.txt");
  return CheckThrowing([&] { (void)io::ReadLimapTracks(path, centres); });
}

int ObjLines(const std::uint8_t* data, std::size_t size) {
  const std::filesystem::path path = WriteInput(data, size, "lines.obj");
  return CheckThrowing([&] { (void)io::ReadObjLines(path); });
}

int MeshPly(const std::uint8_t* data, std::size_t size) {
  return Check(io::ReadMesh(WriteInput(data, size, "mesh.ply")));
}

int MeshObj(const std::uint8_t* data, std::size_t size) {
  return Check(io::ReadMesh(WriteInput(data, size, "mesh.obj")));
}

int MeshOff(const std::uint8_t* data, std::size_t size) {
  return Check(io::ReadMesh(WriteInput(data, size, "mesh.off")));
}

constexpr std::array<FuzzTarget, 10> kTargets{{
    {"reference_json", &ReferenceJson},
    {"line3dpp", &Line3dpp},
    {"nvm", &Nvm},
    {"colmap", &Colmap},
    {"colmap_binary", &ColmapBinary},
    {"limap", &Limap},
    {"obj_lines", &ObjLines},
    {"mesh_ply", &MeshPly},
    {"mesh_obj", &MeshObj},
    {"mesh_off", &MeshOff},
}};

}  // namespace

std::span<const FuzzTarget> FuzzTargets() { return kTargets; }

const FuzzTarget& FindFuzzTarget(const char* name) {
  for (const FuzzTarget& t : kTargets) {
    if (std::strcmp(t.name, name) == 0) return t;
  }
  std::fprintf(stderr, "linesurf fuzz: no target named %s\n", name);
  std::abort();
}

}  // namespace linesurf::fuzz
