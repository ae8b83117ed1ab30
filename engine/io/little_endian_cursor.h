#pragma once
// Sequential reads of little-endian binary records (COLMAP .bin models) with the byte offset
// kept for error messages.

#include <bit>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <type_traits>

namespace linesurf::io {

class LittleEndianCursor {
 public:
  explicit LittleEndianCursor(std::string_view data) : data_(data) {}

  /// Reads one arithmetic value; false (nothing consumed) when the data ends first.
  template <typename T>
  bool Read(T& value) {
    static_assert(std::is_arithmetic_v<T>);
    if (data_.size() - pos_ < sizeof(T)) return false;
    unsigned char bytes[sizeof(T)];
    std::memcpy(bytes, data_.data() + pos_, sizeof(T));
    if constexpr (std::endian::native == std::endian::big) {
      for (std::size_t i = 0; i < sizeof(T) / 2; ++i) std::swap(bytes[i], bytes[sizeof(T) - 1 - i]);
    }
    std::memcpy(&value, bytes, sizeof(T));
    pos_ += sizeof(T);
    return true;
  }
  /// Reads a NUL-terminated string; false when no NUL follows.
  bool ReadCString(std::string& value) {
    const std::size_t end = data_.find('\0', pos_);
    if (end == std::string_view::npos) return false;
    value.assign(data_.substr(pos_, end - pos_));
    pos_ = end + 1;
    return true;
  }
  /// Skips `n` bytes; false when fewer remain.
  bool Skip(std::uint64_t n) {
    if (data_.size() - pos_ < n) return false;
    pos_ += static_cast<std::size_t>(n);
    return true;
  }
  [[nodiscard]] std::size_t offset() const { return pos_; }
  [[nodiscard]] bool AtEnd() const { return pos_ == data_.size(); }

 private:
  std::string_view data_;
  std::size_t pos_ = 0;
};

}  // namespace linesurf::io
