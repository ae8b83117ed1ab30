#pragma once
// One declaration per option gives its command-line flag, its entry in a `--config FILE` JSON
// object and its field in the run report (COLMAP's OptionManager pattern): the option's default
// is the one of the options struct it writes into, and exists nowhere else.

#include "linesurf/error.h"

#include <functional>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
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
  /// (if any). kInvalidOptions naming the file and key for an unknown key or a wrong type.
  [[nodiscard]] Status ApplyConfig();
  /// The effective value of every option, keyed as in the config file, in declaration order
  /// (ordered_json so a report lists them as the help does).
  [[nodiscard]] nlohmann::ordered_json Effective() const;

 private:
  struct Entry {
    std::string key;
    CLI::Option* option = nullptr;
    std::function<void(const nlohmann::json&)> set;  ///< throws on a wrong JSON type or value
    std::function<nlohmann::json()> get;
  };

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
  void Register(const std::string& name,
                CLI::Option* option,
                std::function<void(const nlohmann::json&)> set,
                std::function<nlohmann::json()> get);

  CLI::App& app_;
  std::vector<Entry> entries_;
  std::string config_path_;
};

}  // namespace linesurf::cli
