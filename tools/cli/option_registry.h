#pragma once
// The command line and `--config FILE` of a command: the library's options come from their one
// declaration (linesurf/option_schema.h), flag, key and range; the command's own (output format,
// CRS) are added one by one. Defaults are the options structs' own and exist nowhere else.

#include "linesurf/error.h"
#include "linesurf/option_schema.h"

#include <algorithm>
#include <functional>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

namespace linesurf::cli {

class OptionRegistry {
 public:
  /// Options are added to `app`; `--config FILE` is added at once.
  explicit OptionRegistry(CLI::App& app);

  /// Every option of the library's `options` (VisitOptions) but those whose path is in `skip`:
  /// flag `--<spec.flag>`, key spec.path; ApplyConfig checks each value against its spec.
  template <typename Options>
  void AddOptions(Options& options, const std::vector<std::string_view>& skip = {}) {
    VisitOptions(options, [&](const OptionSpec& spec, auto& field) {
      if (std::find(skip.begin(), skip.end(), spec.path) != skip.end()) return;
      using T = std::remove_reference_t<decltype(field)>;
      const std::string flag(spec.flag);
      std::string help(spec.help);
      if constexpr (std::is_same_v<T, bool>) {
        AddFlag(flag, field, help);
      } else if constexpr (std::is_enum_v<T>) {
        AddChoice(flag, field, EnumChoices<T>(), help);
      } else {
        if (const std::string range = OptionRangeText(spec.range); !range.empty()) {
          help += " " + range;
        }
        Add(flag, field, help);
      }
      entries_.back().key = std::string(spec.path);
      entries_.back().violation = [spec, &field] { return OptionValueViolation(spec, field); };
    });
  }

  /// A value option `--<name>` (JSON key: the name with '_' for '-'), writing into `field`.
  template <typename T>
  CLI::Option* Add(const std::string& name, T& field, const std::string& help) {
    CLI::Option* option = app_.add_option("--" + name, field, help)->capture_default_str();
    Register(name, option, Setter(field), [&field] { return nlohmann::json(field); });
    return option;
  }
  /// An optional value: unset is JSON null (and the config may set it to null).
  template <typename T>
  CLI::Option* Add(const std::string& name, std::optional<T>& field, const std::string& help) {
    CLI::Option* option = app_.add_option("--" + name, field, help);
    Register(
        name,
        option,
        [&field](const nlohmann::json& j) {
          if (j.is_null()) {
            field.reset();
          } else {
            field = Convert<T>(j);
          }
        },
        [&field] { return field ? nlohmann::json(*field) : nlohmann::json(); });
    return option;
  }
  /// A boolean flag `--<name>`; JSON true/false.
  CLI::Option* AddFlag(const std::string& name, bool& field, const std::string& help);
  /// An enumeration chosen by name (`names` in the order the help lists them).
  template <typename E>
  CLI::Option* AddChoice(const std::string& name,
                         E& field,
                         const std::vector<std::pair<std::string, E>>& names,
                         const std::string& help) {
    std::map<std::string, E> by_name(names.begin(), names.end());
    std::string listed;
    for (const auto& [text, value] : names) listed += (listed.empty() ? "" : ", ") + text;
    // The help shows the names only ("{detect, given}=detect"), not the mapped values.
    CLI::Option* option = app_.add_option("--" + name, field, help)
                              ->transform(CLI::CheckedTransformer(by_name).description(""))
                              ->type_name("{" + listed + "}")
                              ->default_str(NameOf(field, names));
    Register(
        name,
        option,
        [&field, by_name, listed](const nlohmann::json& j) {
          const auto it = j.is_string() ? by_name.find(j.get<std::string>()) : by_name.end();
          if (it == by_name.end()) throw std::invalid_argument("not one of " + listed);
          field = it->second;
        },
        [&field, names] { return nlohmann::json(NameOf(field, names)); });
    return option;
  }

  /// After parsing: sets every option the command line did not give from the `--config` file
  /// (if any; keys as nested objects {"weights": {"edge": 0.2}} or dotted "weights.edge"), then
  /// checks the library's options against their specs. kInvalidOptions naming the file and key
  /// for an unknown key or a wrong type, naming the flag and path for a value out of range.
  [[nodiscard]] Status ApplyConfig();
  /// The effective value of every option in declaration order (ordered_json so a report lists
  /// them as the help does), nested by the dots of the keys.
  /// `only`: these keys alone (all when empty).
  [[nodiscard]] nlohmann::ordered_json Effective(const std::vector<std::string>& only = {}) const;

 private:
  struct Entry {
    std::string key;
    CLI::Option* option = nullptr;
    std::function<void(const nlohmann::json&)> set;  ///< throws on a wrong JSON type or value
    std::function<nlohmann::json()> get;
    std::function<std::string()> violation;  ///< why the value is refused; library options only
  };

  template <typename E>
  static std::vector<std::pair<std::string, E>> EnumChoices() {
    std::vector<std::pair<std::string, E>> names;
    for (int i = 0; i < OptionEnum<E>::kCount; ++i) {
      names.emplace_back(OptionEnum<E>::Name(static_cast<E>(i)), static_cast<E>(i));
    }
    return names;
  }

  template <typename T>
  static T Convert(const nlohmann::json& j) {
    if constexpr (std::is_same_v<T, bool>) {
      if (!j.is_boolean()) throw std::invalid_argument("expected true or false");
    } else if constexpr (std::is_arithmetic_v<T>) {
      if (!j.is_number()) throw std::invalid_argument("expected a number");
      if constexpr (std::is_integral_v<T>) {
        if (!j.is_number_integer()) throw std::invalid_argument("expected an integer");
      }
    } else if constexpr (std::is_same_v<T, std::string>) {
      if (!j.is_string()) throw std::invalid_argument("expected a string");
    }
    return j.get<T>();
  }
  template <typename T>
  static std::function<void(const nlohmann::json&)> Setter(T& field) {
    return [&field](const nlohmann::json& j) { field = Convert<T>(j); };
  }
  template <typename E>
  static std::string NameOf(E value, const std::vector<std::pair<std::string, E>>& names) {
    for (const auto& [text, v] : names) {
      if (v == value) return text;
    }
    return "?";
  }
  /// kInvalidOptions naming the flag and path of the first library option out of its range.
  [[nodiscard]] Status CheckValues() const;
  void Register(const std::string& name,
                CLI::Option* option,
                std::function<void(const nlohmann::json&)> set,
                std::function<nlohmann::json()> get);

  CLI::App& app_;
  std::vector<Entry> entries_;
  std::string config_path_;
};

}  // namespace linesurf::cli
