#pragma once
// Exact deduplication of viewpoints while a reader builds a scene: equal coordinates share one
// ViewpointId, numbered in first-seen order (every reader uses it, so conversions keep ids).

#include <array>
#include <functional>
#include <unordered_map>

#include "engine/core/geometry.h"
#include "engine/core/strong_id.h"

namespace linesurf::io {

class ViewpointTable {
 public:
  explicit ViewpointTable(IdVector<ViewpointId, Vec3>& viewpoints) : viewpoints_(viewpoints) {}

  /// The id of the viewpoint at `c`, appended to the scene's viewpoints when new.
  ViewpointId Intern(const Vec3& c) {
    const Key key{{c.x() + 0.0, c.y() + 0.0, c.z() + 0.0}};  // + 0.0 folds -0.0 into 0.0
    const auto [it, inserted] = ids_.try_emplace(key, viewpoints_.NextId());
    if (inserted) viewpoints_.push_back(c);
    return it->second;
  }

 private:
  struct Key {
    std::array<double, 3> c;
    bool operator==(const Key& o) const { return c == o.c; }
  };
  struct KeyHash {
    std::size_t operator()(const Key& k) const noexcept {
      std::size_t h = 1469598103934665603ull;  // FNV-1a style mixing of the three hashes
      for (const double v : k.c) h = (h ^ std::hash<double>()(v)) * 1099511628211ull;
      return h;
    }
  };
  IdVector<ViewpointId, Vec3>& viewpoints_;
  std::unordered_map<Key, ViewpointId, KeyHash> ids_;  // lookup only, never iterated
};

}  // namespace linesurf::io
