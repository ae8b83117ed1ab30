#include "tools/cli/option_checks.h"

#include "tools/cli/number_text.h"

#include <cmath>
#include <functional>
#include <string>

namespace linesurf::cli {
namespace {

/// A validator that parses the value as a double and accepts it when `ok` holds.
CLI::Validator NumberCheck(const std::function<bool(double)>& ok, const std::string& what) {
  return CLI::Validator(
      [ok, what](std::string& text) -> std::string {
        double value = 0.0;
        if (!CLI::detail::lexical_cast(text, value)) return "'" + text + "' is not a number";
        if (!ok(value)) return "must be " + what + ", got " + text;
        return {};
      },
      what);
}

}  // namespace

CLI::Validator AtLeast(double lo) {
  return NumberCheck([lo](double v) { return v >= lo; }, ">= " + ShortNumber(lo));
}

CLI::Validator Above(double lo) {
  return NumberCheck([lo](double v) { return v > lo; }, "> " + ShortNumber(lo));
}

CLI::Validator Between(double lo, double hi) {
  return NumberCheck([lo, hi](double v) { return v >= lo && v <= hi; },
                     "in [" + ShortNumber(lo) + ", " + ShortNumber(hi) + "]");
}

void AddTypeChecks(CLI::App& root) {
  for (CLI::Option* option : root.get_options()) {
    // "FLOAT" or "UINT", followed by ":<check>" once a check with a description is added.
    const std::string full_type = option->get_type_name();
    const std::string type = full_type.substr(0, full_type.find(':'));
    if (type == "UINT") {
      option->check(CLI::Validator(
          [](std::string& text) -> std::string {
            const auto first = text.find_first_not_of(" \t");
            if (first != std::string::npos && text[first] == '-') {
              return "must be >= 0, got " + text;
            }
            return {};
          },
          ""));
    } else if (type == "FLOAT") {
      CLI::Validator finite =
          NumberCheck([](double v) { return std::isfinite(v); }, "a finite number");
      option->check(finite.description(""));
    }
  }
  for (CLI::App* sub : root.get_subcommands([](CLI::App*) { return true; })) AddTypeChecks(*sub);
}

}  // namespace linesurf::cli
