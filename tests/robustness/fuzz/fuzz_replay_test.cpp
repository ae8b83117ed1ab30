// Replays the committed corpus and crash reproducers of every fuzz target through the same entry
// point as the fuzzers, with the normal compiler, in the normal CTest suite: a reader that crashes,
// aborts or gives an internal error on one of them fails here.

#include "tests/robustness/fuzz/fuzz_targets.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace linesurf::fuzz {
namespace {

std::vector<std::filesystem::path> FilesUnder(const std::filesystem::path& dir) {
  std::vector<std::filesystem::path> files;
  if (!std::filesystem::is_directory(dir)) return files;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    if (entry.is_regular_file()) files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

class FuzzReplay : public ::testing::TestWithParam<FuzzTarget> {};

TEST_P(FuzzReplay, CorpusAndReproducersReadWithoutFinding) {
  const FuzzTarget& target = GetParam();
  const std::filesystem::path root(LINESURF_FUZZ_DIR);
  const std::vector<std::filesystem::path> corpus = FilesUnder(root / "corpus" / target.name);
  ASSERT_FALSE(corpus.empty()) << "no seed corpus in " << (root / "corpus" / target.name);
  std::vector<std::filesystem::path> files = corpus;
  const std::vector<std::filesystem::path> reproducers =
      FilesUnder(root / "reproducers" / target.name);
  files.insert(files.end(), reproducers.begin(), reproducers.end());
  for (const std::filesystem::path& file : files) {
    std::ifstream in(file, std::ios::binary);
    const std::vector<char> bytes((std::istreambuf_iterator<char>(in)),
                                  std::istreambuf_iterator<char>());
    SCOPED_TRACE(file.string());
    EXPECT_EQ(target.run(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size()), 0);
  }
}

INSTANTIATE_TEST_SUITE_P(Readers,
                         FuzzReplay,
                         ::testing::ValuesIn(FuzzTargets().begin(), FuzzTargets().end()),
                         [](const ::testing::TestParamInfo<FuzzTarget>& info) {
                           return std::string(info.param.name);
                         });

}  // namespace
}  // namespace linesurf::fuzz
