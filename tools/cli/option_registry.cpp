#include "tools/cli/option_registry.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace linesurf::cli {
namespace {

constexpr const char* kOptionRegistryStage = "config";

/// {"weights": {"edge": 0.2}, "seed": 1} as {"weights.edge": 0.2, "seed": 1}.
void FlattenInto(const nlohmann::json& object,
                 const std::string& prefix,
                 std::vector<std::pair<std::string, nlohmann::json>>& out) {
  for (const auto& item : object.items()) {
    const std::string key = prefix + item.key();
    if (item.value().is_object()) {
      FlattenInto(item.value(), key + ".", out);
    } else {
      out.emplace_back(key, item.value());
    }
  }
}

}  // namespace

OptionRegistry::OptionRegistry(CLI::App& app) : app_(app) {
  app_.add_option("--config",
                  config_path_,
                  "JSON object of options (keys: the flags without '--', '_' for '-'); flags on "
                  "the command line win");
}

CLI::Option* OptionRegistry::AddFlag(const std::string& name,
                                     bool& field,
                                     const std::string& help) {
  CLI::Option* option = app_.add_flag("--" + name, field, help);
  Register(name, option, Setter(field), [&field] { return nlohmann::json(field); });
  return option;
}

void OptionRegistry::Register(const std::string& name,
                              CLI::Option* option,
                              std::function<void(const nlohmann::json&)> set,
                              std::function<nlohmann::json()> get) {
  std::string key = name;
  std::replace(key.begin(), key.end(), '-', '_');
  entries_.push_back({std::move(key), option, std::move(set), std::move(get), {}});
}

Status OptionRegistry::ApplyConfig() {
  if (config_path_.empty()) return CheckValues();
  // A config file that cannot be read is bad input (exit 3); one naming a wrong option or value
  // is a usage error (exit 2), as the same mistake on the command line would be.
  auto unreadable = [&](const std::string& message) {
    return Error{ErrorCode::kInvalidInput, kOptionRegistryStage, config_path_ + ": " + message};
  };
  auto bad = [&](const std::string& message) {
    return Error{ErrorCode::kInvalidOptions, kOptionRegistryStage, config_path_ + ": " + message};
  };
  std::error_code ec;
  if (!std::filesystem::is_regular_file(config_path_, ec)) return unreadable("no such file");
  std::ifstream in(config_path_);
  std::stringstream text;
  text << in.rdbuf();
  if (!in) return unreadable("cannot be read");
  const nlohmann::json config = nlohmann::json::parse(text.str(), nullptr, false);
  if (config.is_discarded()) return unreadable("not valid JSON");
  if (!config.is_object()) return unreadable("expected a JSON object {\"option\": value, ...}");
  std::vector<std::pair<std::string, nlohmann::json>> items;
  FlattenInto(config, "", items);
  for (const auto& item : items) {
    // Named, not a structured binding: clang 14 (sanitizer build) cannot capture one.
    const std::string& key = item.first;
    const nlohmann::json& value = item.second;
    const auto it = std::find_if(
        entries_.begin(), entries_.end(), [&](const Entry& e) { return e.key == key; });
    if (it == entries_.end()) return bad("'" + key + "' is not an option of this command");
    if (it->option->count() > 0) continue;  // given on the command line
    try {
      it->set(value);
    } catch (const std::exception& e) {
      return bad("'" + key + "': " + value.dump() + ": " + e.what());
    }
  }
  return CheckValues();
}

Status OptionRegistry::CheckValues() const {
  for (const Entry& e : entries_) {
    if (!e.violation) continue;
    if (const std::string why = e.violation(); !why.empty()) {
      std::string message = e.option->get_name();
      message += " (";
      message += e.key;
      message += ") ";
      message += why;
      return Error{ErrorCode::kInvalidOptions, "options", message};
    }
  }
  return {};
}

nlohmann::ordered_json OptionRegistry::Effective(const std::vector<std::string>& only) const {
  nlohmann::ordered_json j = nlohmann::ordered_json::object();
  for (const Entry& e : entries_) {
    if (!only.empty() && std::find(only.begin(), only.end(), e.key) == only.end()) continue;
    nlohmann::ordered_json* node = &j;
    std::string_view rest = e.key;
    for (std::size_t dot; (dot = rest.find('.')) != std::string_view::npos;
         rest.remove_prefix(dot + 1)) {
      node = &(*node)[std::string(rest.substr(0, dot))];
    }
    (*node)[std::string(rest)] = e.get();
  }
  return j;
}

}  // namespace linesurf::cli
