#include "tools/cli/output_files.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <system_error>

#include <unistd.h>

namespace linesurf::cli {
namespace fs = std::filesystem;

const std::vector<std::string> kMeshExtensions = {".ply", ".obj", ".off"};
const std::vector<std::string> kJsonExtensions = {".json"};

namespace {

/// The extension of `path`, lower-case, with its dot ("" when it has none).
std::string LowerExtension(const fs::path& path) {
  std::string ext = path.extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

std::string JoinExtensions(const std::vector<std::string>& extensions) {
  std::string text;
  for (std::size_t i = 0; i < extensions.size(); ++i) {
    if (i > 0) text += i + 1 == extensions.size() ? " or " : ", ";
    text += extensions[i];
  }
  return text;
}

/// The absolute, symlink-resolved spelling of `path` (as far as it exists), for comparisons.
fs::path Canonical(const fs::path& path) {
  std::error_code ec;
  fs::path canonical = fs::weakly_canonical(fs::absolute(path, ec), ec);
  return ec ? path.lexically_normal() : canonical;
}

bool SameFile(const fs::path& a, const fs::path& b) {
  std::error_code ec;
  if (fs::exists(a, ec) && fs::exists(b, ec)) return fs::equivalent(a, b, ec) && !ec;
  return Canonical(a) == Canonical(b);
}

}  // namespace

OutputFiles::OutputFiles(std::string stage) : stage_(std::move(stage)) {}

OutputFiles::~OutputFiles() {
  RemoveStaged();
  if (!committed_) RemoveCreatedDirectories();
}

Status OutputFiles::CreateDirectories(const std::string& option, const fs::path& dir) {
  std::vector<fs::path> missing;  // dir and the parents it lacks, deepest first
  std::error_code ec;
  for (fs::path p = dir; !p.empty() && !fs::exists(fs::symlink_status(p, ec));
       p = p.parent_path()) {
    missing.push_back(p);
    if (p == p.parent_path()) break;
  }
  for (auto p = missing.rbegin(); p != missing.rend(); ++p) {
    if (!fs::create_directory(*p, ec) || ec) {
      return Error{ErrorCode::kInvalidOptions,
                   stage_,
                   dir.string() + ": " + option + ": cannot create directory: " +
                       (ec ? ec.message() : "it appeared meanwhile")};
    }
    created_directories_.push_back(*p);
  }
  if (!fs::is_directory(dir, ec)) {
    return Error{ErrorCode::kInvalidOptions,
                 stage_,
                 dir.string() + ": " + option + ": exists and is not a directory"};
  }
  return {};
}

void OutputFiles::AddInput(const fs::path& path) {
  if (!path.empty()) inputs_.push_back(path);
}

void OutputFiles::AddOutput(const std::string& option,
                            const fs::path& path,
                            const std::vector<std::string>& extensions) {
  if (!path.empty()) outputs_.push_back(Output{option, path, extensions, {}});
}

Status OutputFiles::CheckOutput(const Output& output) const {
  const std::string name = output.path.string() + ": " + output.option + ": ";
  const auto refuse = [&](const std::string& why) -> Status {
    return Error{ErrorCode::kInvalidOptions, stage_, name + why};
  };
  const std::string ext = LowerExtension(output.path);
  if (!output.extensions.empty() &&
      std::find(output.extensions.begin(), output.extensions.end(), ext) ==
          output.extensions.end()) {
    return refuse("unknown output format '" + ext + "' (expected " +
                  JoinExtensions(output.extensions) + ")");
  }
  std::error_code ec;
  const fs::file_status status = fs::symlink_status(output.path, ec);
  if (fs::exists(status) && fs::is_directory(fs::status(output.path, ec))) {
    return refuse("is a directory, expected a file name");
  }
  if (fs::exists(status) && !fs::is_regular_file(status) && !fs::is_symlink(status)) {
    return refuse("exists and is not a regular file; it will not be replaced");
  }
  const fs::path dir =
      output.path.parent_path().empty() ? fs::path(".") : output.path.parent_path();
  if (!fs::is_directory(dir, ec)) return refuse("directory " + dir.string() + " does not exist");
  if (::access(dir.c_str(), W_OK | X_OK) != 0) {
    return refuse("directory " + dir.string() + " is not writable");
  }
  for (const fs::path& input : inputs_) {
    if (SameFile(input, output.path)) {
      return refuse("is an input of this run (" + input.string() + "); it will not be overwritten");
    }
  }
  for (const Output& other : outputs_) {
    if (&other == &output) break;
    if (SameFile(other.path, output.path)) {
      return refuse("is also the output of " + other.option + "; give each output its own file");
    }
  }
  return {};
}

Status OutputFiles::Prepare() {
  for (const fs::path& input : inputs_) {
    std::error_code ec;
    if (!fs::exists(input, ec)) {
      return Error{ErrorCode::kInvalidInput, stage_, input.string() + ": no such file"};
    }
  }
  for (const Output& output : outputs_) {
    if (Status s = CheckOutput(output); !s) return s;
  }
  for (std::size_t i = 0; i < outputs_.size(); ++i) {
    Output& output = outputs_[i];
    const fs::path dir = output.path.parent_path();
    std::string name(1, '.');
    name += output.path.filename().string();
    name += ".linesurf-" + std::to_string(::getpid()) + "-" + std::to_string(i);
    name += output.path.extension().string();
    const fs::path staged = dir.empty() ? fs::path(name) : dir / name;
    std::FILE* file = std::fopen(staged.c_str(), "wx");  // proves the directory is writable
    if (file == nullptr || std::fclose(file) != 0) {
      return Error{ErrorCode::kInvalidOptions,
                   stage_,
                   output.path.string() + ": " + output.option + ": cannot create a file in " +
                       (dir.empty() ? std::string(".") : dir.string())};
    }
    output.staged = staged;
  }
  return {};
}

Status OutputFiles::Write(const fs::path& final_path,
                          const std::function<Status(const fs::path&)>& write) const {
  const auto output = std::find_if(outputs_.begin(), outputs_.end(), [&](const Output& o) {
    return o.path == final_path && !o.staged.empty();
  });
  if (output == outputs_.end()) {
    return Error{ErrorCode::kInternal, stage_, final_path.string() + ": not a prepared output"};
  }
  Status written = write(output->staged);
  if (written) return written;
  Error error = written.error();
  const std::string staged = output->staged.string();
  for (std::size_t at = error.message.find(staged); at != std::string::npos;
       at = error.message.find(staged, at)) {
    error.message.replace(at, staged.size(), final_path.string());
    at += final_path.string().size();
  }
  return error;
}

Status OutputFiles::Commit() {
  // The file an output replaces is kept under a second name (a hard link, else a copy) until
  // every rename succeeded, so that a failed rename can put it back.
  std::vector<fs::path> kept(outputs_.size());
  const auto drop_kept = [&] {
    for (const fs::path& old : kept) {
      std::error_code ignored;
      if (!old.empty()) fs::remove(old, ignored);
    }
  };
  for (std::size_t i = 0; i < outputs_.size(); ++i) {
    std::error_code ec;
    if (!fs::exists(fs::symlink_status(outputs_[i].path, ec))) continue;
    fs::path old = outputs_[i].staged;
    old += ".old";
    fs::create_hard_link(outputs_[i].path, old, ec);
    if (ec) fs::copy_file(outputs_[i].path, old, fs::copy_options::overwrite_existing, ec);
    if (ec) {
      drop_kept();
      return Error{ErrorCode::kInvalidInput,
                   stage_,
                   outputs_[i].path.string() + ": " + outputs_[i].option +
                       ": cannot keep the file it replaces until the end: " + ec.message()};
    }
    kept[i] = old;
  }
  for (std::size_t i = 0; i < outputs_.size(); ++i) {
    Output& output = outputs_[i];
    std::error_code ec;
    fs::rename(output.staged, output.path, ec);
    if (ec) {
      for (std::size_t j = 0; j < i; ++j) {  // take back what this run already put in place
        std::error_code ignored;
        if (kept[j].empty()) {
          fs::remove(outputs_[j].path, ignored);
        } else {
          fs::rename(kept[j], outputs_[j].path, ignored);
        }
      }
      drop_kept();
      return Error{
          ErrorCode::kInvalidInput,
          stage_,
          output.path.string() + ": " + output.option + ": cannot be written: " + ec.message()};
    }
  }
  for (Output& output : outputs_) output.staged.clear();
  drop_kept();
  committed_ = true;
  return {};
}

void OutputFiles::RemoveStaged() noexcept {
  for (Output& output : outputs_) {
    if (output.staged.empty()) continue;
    std::error_code ignored;
    fs::remove(output.staged, ignored);
    fs::path tmp = output.staged;
    tmp += ".tmp";  // io::WriteFileAtomically's own temporary, if a write failed half-way
    fs::remove(tmp, ignored);
    output.staged.clear();
  }
}

void OutputFiles::RemoveCreatedDirectories() noexcept {
  for (auto dir = created_directories_.rbegin(); dir != created_directories_.rend(); ++dir) {
    std::error_code ignored;
    fs::remove(*dir, ignored);  // only when empty: never what someone else put there
  }
  created_directories_.clear();
}

}  // namespace linesurf::cli
