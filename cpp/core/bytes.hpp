// Plain values and vectors of them as bytes and back, to cross to a child process and back (child_process.hpp):
// each value as it is in memory (the child is a fork of this program), a vector as its size and its items.
#pragma once
#include <cstdint>
#include <cstring>
#include <string>
#include <type_traits>
#include <vector>

#include "core/error.hpp"

namespace hexlayer {

class ByteWriter {
 public:
  // [in] value: a trivially copyable value, or a vector of them (or of vectors of them).
  template <class T>
  void put(const T& value) {
    static_assert(std::is_trivially_copyable_v<T>);
    bytes_.append(reinterpret_cast<const char*>(&value), sizeof value);
  }
  template <class T>
  void put(const std::vector<T>& items) {
    put(static_cast<std::uint64_t>(items.size()));
    if constexpr (std::is_trivially_copyable_v<T>)
      bytes_.append(reinterpret_cast<const char*>(items.data()), items.size() * sizeof(T));
    else
      for (const T& item : items) put(item);
  }
  const std::string& bytes() const { return bytes_; }

 private:
  std::string bytes_;
};

class ByteReader {
 public:
  // [in] bytes: a ByteWriter's, read in the order they were put; kept by reference.
  explicit ByteReader(const std::string& bytes) : bytes_(bytes) {}
  // [out] value: the next one. Throws internalError if the bytes end first.
  template <class T>
  void get(T& value) {
    static_assert(std::is_trivially_copyable_v<T>);
    take(&value, sizeof value);
  }
  template <class T>
  void get(std::vector<T>& items) {
    std::uint64_t size = 0;
    get(size);
    if (size > bytes_.size()) throw internalError("bytes from another process cut short");
    items.resize(size);
    if constexpr (std::is_trivially_copyable_v<T>)
      take(items.data(), items.size() * sizeof(T));
    else
      for (T& item : items) get(item);
  }

 private:
  void take(void* to, std::size_t size) {
    if (bytes_.size() - at_ < size) throw internalError("bytes from another process cut short");
    std::memcpy(to, bytes_.data() + at_, size);
    at_ += size;
  }
  const std::string& bytes_;
  std::size_t at_ = 0;
};

}  // namespace hexlayer
