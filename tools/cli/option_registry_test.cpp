#include "tools/cli/option_registry.h"

#include "tests/support/test_paths.h"

#include <gtest/gtest.h>

#include <fstream>
#include <optional>

namespace linesurf::cli {
namespace {

enum class Mode { kFast, kExact };

/// An options struct as the commands have them: the defaults live here only.
struct Options {
  double epsilon = 0.02;
  int iterations = 100;
  std::optional<double> sigma;
  bool verbose = false;
  Mode mode = Mode::kExact;
};

struct Fixture {
  CLI::App app{"test"};
  Options options;
  OptionRegistry registry{app};
  Fixture() {
    registry.Add("epsilon", options.epsilon, "eps");
    registry.Add("max-iterations", options.iterations, "iterations");
    registry.Add("sigma", options.sigma, "sigma");
    registry.AddFlag("verbose", options.verbose, "verbose");
    registry.AddChoice(
        "mode", options.mode, {{"fast", Mode::kFast}, {"exact", Mode::kExact}}, "mode");
  }
  void Parse(std::vector<std::string> args) {
    std::reverse(args.begin(), args.end());  // CLI11 takes the arguments last first
    app.parse(args);
  }
};

std::string WriteConfig(const std::string& text) {
  const auto path = testing::FreshTempDir() / "config.json";
  std::ofstream(path) << text;
  return path.string();
}

TEST(OptionRegistry, DefaultsComeFromTheOptionsStruct) {
  Fixture f;
  f.Parse({});
  ASSERT_TRUE(f.registry.ApplyConfig());
  EXPECT_EQ(f.registry.Effective().dump(),
            R"({"epsilon":0.02,"max_iterations":100,"sigma":null,"verbose":false,"mode":"exact"})");
  // The help shows the same defaults.
  const std::string help = f.app.help();
  EXPECT_NE(help.find("0.02"), std::string::npos) << help;
  EXPECT_NE(help.find("exact"), std::string::npos) << help;
}

TEST(OptionRegistry, FlagsSetTheStruct) {
  Fixture f;
  f.Parse({"--epsilon", "0.5", "--sigma", "2", "--verbose", "--mode", "fast"});
  ASSERT_TRUE(f.registry.ApplyConfig());
  EXPECT_EQ(f.options.epsilon, 0.5);
  EXPECT_EQ(f.options.sigma, 2.0);
  EXPECT_TRUE(f.options.verbose);
  EXPECT_EQ(f.options.mode, Mode::kFast);
  EXPECT_EQ(f.registry.Effective()["mode"], "fast");
}

TEST(OptionRegistry, ConfigFillsWhatTheCommandLineDidNotGive) {
  Fixture f;
  const std::string config = WriteConfig(
      R"({"epsilon": 0.1, "max_iterations": 7, "sigma": 1.5, "verbose": true, "mode": "fast"})");
  f.Parse({"--config", config, "--epsilon", "0.5"});
  ASSERT_TRUE(f.registry.ApplyConfig());
  EXPECT_EQ(f.options.epsilon, 0.5);  // the command line wins
  EXPECT_EQ(f.options.iterations, 7);
  EXPECT_EQ(f.options.sigma, 1.5);
  EXPECT_TRUE(f.options.verbose);
  EXPECT_EQ(f.options.mode, Mode::kFast);
}

TEST(OptionRegistry, BadConfigsNameTheFileAndKey) {
  struct Case {
    const char* text;
    ErrorCode code;
    const char* expected;
  };
  const Case cases[] = {
      {R"({"epsilon": 0.1, "epsilonn": 2})",
       ErrorCode::kInvalidOptions,
       "'epsilonn' is not an option of this command"},
      {R"({"max_iterations": 1.5})",
       ErrorCode::kInvalidOptions,
       "'max_iterations': 1.5: expected an integer"},
      {R"({"mode": "slow"})", ErrorCode::kInvalidOptions, "'mode': \"slow\": not one of"},
      {R"({"verbose": 1})", ErrorCode::kInvalidOptions, "'verbose': 1: expected true or false"},
      {R"([1, 2])", ErrorCode::kInvalidInput, "expected a JSON object"},
      {R"({"epsilon": )", ErrorCode::kInvalidInput, "not valid JSON"},
  };
  for (const Case& c : cases) {
    Fixture f;
    const std::string config = WriteConfig(c.text);
    f.Parse({"--config", config});
    const Status s = f.registry.ApplyConfig();
    ASSERT_FALSE(s) << c.text;
    EXPECT_EQ(s.error().code, c.code) << c.text;
    EXPECT_NE(s.error().message.find(config + ": "), std::string::npos) << s.error().message;
    EXPECT_NE(s.error().message.find(c.expected), std::string::npos) << s.error().message;
  }
  Fixture f;
  f.Parse({"--config", "/nonexistent/config.json"});
  const Status s = f.registry.ApplyConfig();
  ASSERT_FALSE(s);
  EXPECT_EQ(s.error().code, ErrorCode::kInvalidInput);
  EXPECT_NE(s.error().message.find("no such file"), std::string::npos);
}

}  // namespace
}  // namespace linesurf::cli
