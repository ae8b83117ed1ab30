// Hostile cases of kind "signal": SIGINT and SIGTERM sent to a running `detect` and
// `reconstruct` once the stage to interrupt has started; the contract is exit 5 (cancelled)
// and no file written.

#include "engine/io/reference_json.h"
#include "tests/robustness/hostile_case.h"
#include "tests/robustness/hostile_cases.h"
#include "tools/gen/synthesize.h"

#include <stdexcept>
#include <string>

namespace linesurf::robustness {
namespace fs = std::filesystem;

namespace {

// The synthetic city (2632 segments): its detection and its cell complex last seconds, far
// longer than the wait between the stage's first progress line and the signal.
void CityScene(const fs::path& dir) {
  synth::SynthSpec spec;
  spec.family = "city";
  const Expected<synth::SyntheticScene> city = synth::Synthesize(spec);
  if (!city || !io::WriteReferenceJson(city->scene, dir / "city.json")) {
    throw std::runtime_error("cannot write the synthetic city into " + dir.string());
  }
}

}  // namespace

std::vector<HostileCase> SignalCases() {
  struct Interrupted {
    std::string command;
    std::string args;
    std::string stage;  // the progress line that shows the stage is running
  };
  const std::vector<Interrupted> runs = {
      {"detect", "detect city.json -o planes.json", "[detect_planes]"},
      {"reconstruct", "reconstruct city.json -o out.ply --report report.json", "[cell_complex]"},
  };
  std::vector<HostileCase> cases;
  for (const Interrupted& run : runs) {
    for (const auto& [name, signal] : {std::pair{"sigint", "INT"}, {"sigterm", "TERM"}}) {
      HostileCase c;
      c.kind = "signal";
      c.name = run.command + "_" + name;
      c.make = CityScene;
      c.args = run.args;
      c.exit_code = 5;
      c.message = {"cancelled"};
      c.during = std::string("kill -") + signal + " $pid";
      c.during_when = run.stage;
      cases.push_back(std::move(c));
    }
  }
  return cases;
}

}  // namespace linesurf::robustness
