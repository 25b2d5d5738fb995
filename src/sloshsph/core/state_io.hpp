#pragma once
// Binary state files (checkpoints): a header, then named, typed, length-prefixed records, so
// that a damaged, truncated or foreign file is reported by name instead of read as garbage.
// Values are written as their bytes (the reader must be the same build architecture: a
// checkpoint continues a run on the machine kind that wrote it; the header records the sizes).
#include <cstdint>
#include <cstring>
#include <string>
#include <type_traits>
#include <vector>

namespace sloshsph {

class StateWriter {
 public:
  StateWriter();  // writes the header
  template <class T>
  void value(const std::string& name, const T& v) {
    static_assert(std::is_trivially_copyable_v<T>);
    record(name, sizeof(T), 1, &v);
  }
  template <class T>
  void array(const std::string& name, const std::vector<T>& v) {
    static_assert(std::is_trivially_copyable_v<T>);
    record(name, sizeof(T), v.size(), v.data());
  }
  void text(const std::string& name, const std::string& s) { record(name, 1, s.size(), s.data()); }
  const std::string& bytes() const { return out_; }

 private:
  void record(const std::string& name, std::size_t element_size, std::size_t count, const void* data);
  std::string out_;
};

// Reads records in the order they were written. Every mismatch (name, element size, a
// truncated file, a bad header) throws InputError(source, "", what) naming the record.
class StateReader {
 public:
  StateReader(std::string bytes, std::string source);
  template <class T>
  T value(const std::string& name) {
    static_assert(std::is_trivially_copyable_v<T>);
    T v;
    const std::size_t count = expect(name, sizeof(T));
    if (count != 1) fail(name, "holds " + std::to_string(count) + " values, expected 1");
    take(&v, sizeof(T), name);
    return v;
  }
  template <class T>
  std::vector<T> array(const std::string& name) {
    static_assert(std::is_trivially_copyable_v<T>);
    const std::size_t count = expect(name, sizeof(T));
    std::vector<T> v(count);
    take(v.data(), count * sizeof(T), name);
    return v;
  }
  std::string text(const std::string& name);
  // Whether the next record is `name` (for a record that later versions added: an older
  // checkpoint without it stays readable).
  bool next_is(const std::string& name) const;
  bool at_end() const { return position_ == bytes_.size(); }

 private:
  std::size_t expect(const std::string& name, std::size_t element_size);
  void take(void* out, std::size_t n, const std::string& name);
  [[noreturn]] void fail(const std::string& name, const std::string& what) const;
  std::string bytes_;
  std::string source_;
  std::size_t position_ = 0;
};

}  // namespace sloshsph
