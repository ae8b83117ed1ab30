// `linesurf options [--json]`: every option of reconstruct and detect from its one declaration
// (linesurf/option_schema.h): the path that names it in --config files, reports, the C API and
// Python, its flag, type, default, range and help. docs/user/cli_reference.md embeds the table.

#include "linesurf/option_schema.h"

#include "tools/cli/commands.h"

#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <type_traits>

#include <nlohmann/json.hpp>

namespace linesurf::cli {
namespace {

struct OptionRow {
  std::string path, flag, group, type, default_value, range, help;
};

std::string Number(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", x);
  return text;
}

template <typename T>
std::string TypeOf() {
  if constexpr (std::is_same_v<T, bool>) {
    return "flag";
  } else if constexpr (std::is_enum_v<T>) {
    std::string names;
    for (int i = 0; i < OptionEnum<T>::kCount; ++i) {
      names += (i ? ", " : "") + std::string(OptionEnum<T>::Name(static_cast<T>(i)));
    }
    return "one of " + names;
  } else if constexpr (std::is_same_v<T, std::optional<double>>) {
    return "real or unset";
  } else if constexpr (std::is_integral_v<T>) {
    return "integer";
  } else {
    return "real";
  }
}

template <typename T>
std::string ValueText(const T& value) {
  if constexpr (std::is_same_v<T, bool>) {
    return value ? "true" : "false";
  } else if constexpr (std::is_enum_v<T>) {
    return OptionEnum<T>::Name(value);
  } else if constexpr (std::is_same_v<T, std::optional<double>>) {
    return value ? Number(*value) : "unset";
  } else if constexpr (std::is_integral_v<T>) {
    return std::to_string(value);
  } else {
    return Number(value);
  }
}

std::vector<OptionRow> Rows() {
  std::vector<OptionRow> rows;
  const ReconstructOptions defaults;
  VisitOptions(defaults, [&](const OptionSpec& spec, const auto& field) {
    using T = std::remove_cvref_t<decltype(field)>;
    const bool number = std::is_arithmetic_v<T> && !std::is_same_v<T, bool>;
    const bool global = spec.path == "num_threads";  // the CLI's -j before the subcommand
    rows.push_back({std::string(spec.path),
                    global ? "-j, --threads (global)" : "--" + std::string(spec.flag),
                    std::string(spec.group),
                    TypeOf<T>(),
                    ValueText(field),
                    number || std::is_same_v<T, std::optional<double>> ? OptionRangeText(spec.range)
                                                                      : std::string(),
                    std::string(spec.help)});
  });
  return rows;
}

void PrintMarkdown(const std::vector<OptionRow>& rows) {
  std::string group;
  for (const OptionRow& r : rows) {
    if (r.group != group) {
      group = r.group;
      std::cout << (group == rows.front().group ? "" : "\n") << "### " << group << "\n\n"
                << "| path | flag | type | default | range | meaning |\n"
                << "|---|---|---|---|---|---|\n";
    }
    std::cout << "| `" << r.path << "` | `" << r.flag << "` | " << r.type << " | "
              << r.default_value << " | " << r.range << " | " << r.help << " |\n";
  }
}

}  // namespace

Command AddOptionsCommand(CLI::App& app, CommonOptions& /*common*/) {
  auto json = std::make_shared<bool>(false);
  Command cmd;
  cmd.app = app.add_subcommand(
      "options",
      "List the options of reconstruct and detect: path (--config key, report, C and Python "
      "name), flag, type, default, range");
  cmd.app->add_flag("--json", *json, "A JSON array instead of Markdown tables");
  cmd.run = [json] {
    const std::vector<OptionRow> rows = Rows();
    if (*json) {
      nlohmann::ordered_json out = nlohmann::ordered_json::array();
      for (const OptionRow& r : rows) {
        out.push_back({{"path", r.path},
                       {"flag", r.flag},
                       {"group", r.group},
                       {"type", r.type},
                       {"default", r.default_value},
                       {"range", r.range},
                       {"help", r.help}});
      }
      std::cout << out.dump(2) << "\n";
    } else {
      PrintMarkdown(rows);
    }
    return kExitOk;
  };
  return cmd;
}

}  // namespace linesurf::cli
