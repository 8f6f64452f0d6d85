// Named values kept as their bytes, for checkpoints. The state a run carries
// from one step to the next is saved and restored by one visitor
// (engine/carried_state.hpp), called with a StateWriter or a StateReader,
// so that what is saved and what is restored cannot drift apart. Values
// are plain data (numbers, fixed-size vectors and tensors, the models'
// states): their bytes are their value, so a restored value is
// bit-identical to the saved one.
#pragma once
#include <cstring>
#include <map>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace flowmpm {

// Record name -> the value's bytes.
using StateRecords = std::map<std::string, std::string>;

// No pointer and no owned memory: the bytes are the value. Eigen's
// fixed-size vectors and quaternions are plain data, though not formally
// trivially copyable (Eigen declares their copy constructors).
template <class T>
concept PlainData = std::is_standard_layout_v<T> && std::is_trivially_destructible_v<T> && !std::is_pointer_v<T>;

// Saves each value it is called with.
class StateWriter {
 public:
  explicit StateWriter(StateRecords& records) : records_(records) {}
  template <PlainData T>
  void operator()(const std::string& name, const T& value) {
    put(name, &value, sizeof(T));
  }
  template <PlainData T>
  void operator()(const std::string& name, const std::vector<T>& values) {
    put(name, values.data(), values.size() * sizeof(T));
  }
  void operator()(const std::string& name, const std::string& text) { put(name, text.data(), text.size()); }

 private:
  void put(const std::string& name, const void* data, std::size_t size) {
    if (!records_.emplace(name, std::string(static_cast<const char*>(data), size)).second)
      throw std::logic_error("state record " + name + " saved twice");
  }
  StateRecords& records_;
};

// Restores each value it is called with; throws std::runtime_error naming
// the record when it is missing or its size does not fit the value.
class StateReader {
 public:
  explicit StateReader(const StateRecords& records) : records_(records) {}
  template <PlainData T>
  void operator()(const std::string& name, T& value) const {
    const std::string& bytes = get(name);
    if (bytes.size() != sizeof(T)) mismatch(name, bytes.size(), sizeof(T));
    std::memcpy(static_cast<void*>(&value), bytes.data(), sizeof(T));
  }
  template <PlainData T>
  void operator()(const std::string& name, std::vector<T>& values) const {
    const std::string& bytes = get(name);
    if (bytes.size() % sizeof(T) != 0) mismatch(name, bytes.size(), sizeof(T));
    values.resize(bytes.size() / sizeof(T));
    if (!values.empty()) std::memcpy(static_cast<void*>(values.data()), bytes.data(), bytes.size());
  }
  void operator()(const std::string& name, std::string& text) const { text = get(name); }

 private:
  const std::string& get(const std::string& name) const {
    const auto found = records_.find(name);
    if (found == records_.end()) throw std::runtime_error("it has no record " + name);
    return found->second;
  }
  [[noreturn]] static void mismatch(const std::string& name, std::size_t size, std::size_t value_size) {
    throw std::runtime_error("its record " + name + " has " + std::to_string(size) +
                             " bytes, which do not fit values of " + std::to_string(value_size) + " bytes");
  }
  const StateRecords& records_;
};

}  // namespace flowmpm
