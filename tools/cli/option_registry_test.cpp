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

// The library's options come from their one declaration: flag, path key (nested or dotted in a
// config), and a range check naming both.
TEST(OptionRegistry, SchemaOptionsTakeTheirFlagsKeysAndRanges) {
  CLI::App app{"test"};
  ReconstructOptions options;
  OptionRegistry registry{app};
  registry.AddOptions(options, {"num_threads"});
  EXPECT_EQ(app.get_option_no_throw("--threads"), nullptr);
  ASSERT_NE(app.get_option_no_throw("--w-visibility"), nullptr);
  const std::string config =
      WriteConfig(R"({"weights": {"edge": 0.25}, "detection.support_gap": 4, "engine": "blocks"})");
  std::vector<std::string> args = {"0.5", "--w-visibility", config, "--config"};
  app.parse(args);
  ASSERT_TRUE(registry.ApplyConfig());
  EXPECT_EQ(options.weights.visibility, 0.5);
  EXPECT_EQ(options.weights.edge, 0.25);
  EXPECT_EQ(options.detection.support_gap, 4.0);
  const nlohmann::ordered_json effective = registry.Effective();
  EXPECT_EQ(effective["weights"]["edge"], 0.25);
  EXPECT_EQ(effective["plane_source"], "detect");
  EXPECT_FALSE(effective.contains("num_threads"));

  CLI::App app2{"test"};
  ReconstructOptions options2;
  OptionRegistry registry2{app2};
  registry2.AddOptions(options2);
  std::vector<std::string> bad = {"1001", "--support-gap"};
  app2.parse(bad);
  const Status s = registry2.ApplyConfig();
  ASSERT_FALSE(s);
  EXPECT_EQ(s.error().code, ErrorCode::kInvalidOptions);
  EXPECT_EQ(s.error().message, "--support-gap (detection.support_gap) must be in [0, 1000]");
}

}  // namespace
}  // namespace linesurf::cli
