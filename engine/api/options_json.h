#pragma once
// The options as JSON, by their schema paths (linesurf/option_schema.h), nested at the dots
// ({"weights": {"edge": 0.1}}), enums by name, unset optionals as null: written into the run
// reports and the work units' inputs, read back by the units.

#include <string>
#include <string_view>
#include <type_traits>

#include <nlohmann/json.hpp>

#include "engine/core/exception.h"
#include "linesurf/option_schema.h"

namespace linesurf::api {

template <typename Options>
nlohmann::ordered_json OptionsJson(const Options& options) {
  nlohmann::ordered_json j = nlohmann::ordered_json::object();
  VisitOptions(options, [&j](const OptionSpec& spec, const auto& field) {
    nlohmann::ordered_json* node = &j;
    std::string_view rest = spec.path;
    for (std::size_t dot; (dot = rest.find('.')) != std::string_view::npos;
         rest.remove_prefix(dot + 1)) {
      node = &(*node)[std::string(rest.substr(0, dot))];
    }
    using T = std::remove_cvref_t<decltype(field)>;
    nlohmann::ordered_json& value = (*node)[std::string(rest)];
    if constexpr (std::is_enum_v<T>) {
      value = OptionEnum<T>::Name(field);
    } else if constexpr (std::is_same_v<T, std::optional<double>>) {
      value = field ? nlohmann::ordered_json(*field) : nlohmann::ordered_json();
    } else {
      value = field;
    }
  });
  return j;
}

/// Options from OptionsJson's text, every option present; throws kInvalidInput under `stage`
/// naming the first key that is missing or of the wrong kind.
template <typename Options>
Options ReadOptionsJson(const std::string& text, const std::string& stage) {
  const nlohmann::json j = nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
  LINESURF_THROW_IF(!j.is_object(), kInvalidInput, stage, "options: not a JSON object");
  Options options;
  VisitOptions(options, [&](const OptionSpec& spec, auto& field) {
    const nlohmann::json* node = &j;
    std::string_view rest = spec.path;
    for (std::size_t dot; node != nullptr && (dot = rest.find('.')) != std::string_view::npos;
         rest.remove_prefix(dot + 1)) {
      auto it = node->find(std::string(rest.substr(0, dot)));
      node = it == node->end() ? nullptr : &*it;
    }
    const nlohmann::json* value = nullptr;
    if (node != nullptr && node->is_object()) {
      auto it = node->find(std::string(rest));
      if (it != node->end()) value = &*it;
    }
    using T = std::remove_cvref_t<decltype(field)>;
    bool read = value != nullptr;
    if constexpr (std::is_enum_v<T>) {
      const std::optional<T> parsed =
          read && value->is_string() ? OptionEnumFromName<T>(value->get<std::string>())
                                     : std::nullopt;
      read = parsed.has_value();
      if (read) field = *parsed;
    } else if constexpr (std::is_same_v<T, std::optional<double>>) {
      read = read && (value->is_null() || value->is_number());
      if (read) {
        field = value->is_null() ? std::nullopt : std::optional<double>(value->get<double>());
      }
    } else if constexpr (std::is_same_v<T, bool>) {
      read = read && value->is_boolean();
      if (read) field = value->get<bool>();
    } else {
      static_assert(std::is_arithmetic_v<T>, "an option kind ReadOptionsJson does not know");
      read = read && (std::is_integral_v<T> ? value->is_number_integer() : value->is_number());
      if (read) field = value->get<T>();
    }
    LINESURF_THROW_IF(!read, kInvalidInput, stage,
                      "options: '" << spec.path << "' is missing or of the wrong kind");
  });
  return options;
}

}  // namespace linesurf::api
