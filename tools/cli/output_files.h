#pragma once
// The files a subcommand reads and writes, checked before any work and committed at the end:
// a run either writes all of its outputs or none (docs/user/errors.md).

#include "linesurf/error.h"

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace linesurf::cli {

/// Extensions (lower case, with the dot) that the writers of each kind of output understand.
extern const std::vector<std::string> kMeshExtensions;  // .ply .obj .off
extern const std::vector<std::string> kJsonExtensions;  // .json

/// Usage:
///   OutputFiles files("reconstruct");
///   files.AddInput(args.input);
///   files.AddOutput("-o", args.output, kMeshExtensions);
///   if (Status s = files.Prepare(); !s) return ReportError(s.error());
///   files.Write(args.output, [&](const auto& path) { return io::WriteMesh(mesh, path); });
///   if (Status s = files.Commit(); !s) return ReportError(s.error());
/// Outputs are staged as hidden temporary files beside their destination (same directory, same
/// extension, so format detection by extension still works) and renamed into place by Commit();
/// whatever was not committed is removed when the object is destroyed (error, cancel, exception).
class OutputFiles {
 public:
  explicit OutputFiles(std::string stage);
  OutputFiles(const OutputFiles&) = delete;
  OutputFiles& operator=(const OutputFiles&) = delete;
  ~OutputFiles();

  /// A file (or directory) the run reads; an empty path is ignored.
  void AddInput(const std::filesystem::path& path);
  /// Creates `dir` and its missing parents now (an output directory, e.g. synth's -o DIR); the
  /// ones created are removed again unless Commit() succeeds, so a failed run leaves nothing.
  /// kInvalidOptions naming `option` and `dir` when it cannot be created.
  [[nodiscard]] Status CreateDirectories(const std::string& option,
                                         const std::filesystem::path& dir);
  /// A file the run writes, named by `option` in messages; `extensions` empty = any name. An
  /// empty path is ignored (optional output not requested).
  void AddOutput(const std::string& option,
                 const std::filesystem::path& path,
                 const std::vector<std::string>& extensions);

  /// Checks, before any work: every input exists (kInvalidInput naming it, exit 3); every output
  /// has a known extension, is not a directory or special file, lies in an existing writable
  /// directory, is not the same file as an input and not the same path as another output
  /// (kInvalidOptions naming the option and the path, exit 2). Writability is proven by creating
  /// the staged files.
  [[nodiscard]] Status Prepare();

  /// Runs `write` on the staged file of the output destined for `final_path` (as given to
  /// AddOutput); an error it returns names `final_path`, not the temporary file.
  [[nodiscard]] Status Write(
      const std::filesystem::path& final_path,
      const std::function<Status(const std::filesystem::path&)>& write) const;

  /// Renames every staged file onto its destination. If a rename fails (e.g. a directory made
  /// at an output's path since Prepare), the outputs already renamed are taken back and the
  /// files they replaced restored: all of the outputs or none.
  [[nodiscard]] Status Commit();

 private:
  struct Output {
    std::string option;
    std::filesystem::path path;
    std::vector<std::string> extensions;
    std::filesystem::path staged;
  };
  [[nodiscard]] Status CheckOutput(const Output& output) const;
  void RemoveStaged() noexcept;
  void RemoveCreatedDirectories() noexcept;

  std::string stage_;
  std::vector<std::filesystem::path> inputs_;
  std::vector<Output> outputs_;
  std::vector<std::filesystem::path> created_directories_;  ///< parents first
  bool committed_ = false;
};

}  // namespace linesurf::cli
