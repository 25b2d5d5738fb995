#include "sloshsph/core/state_io.hpp"

#include "sloshsph/core/errors.hpp"

namespace sloshsph {
namespace {

constexpr char kMagic[8] = {'S', 'L', 'O', 'S', 'H', 'C', 'K', '1'};

template <class T>
void append(std::string& out, const T& v) {
  out.append(reinterpret_cast<const char*>(&v), sizeof(T));
}

// The header: magic, then the sizes of the types the records hold, which must match.
std::string header() {
  std::string h(kMagic, sizeof kMagic);
  append(h, static_cast<std::uint8_t>(sizeof(double)));
  append(h, static_cast<std::uint8_t>(sizeof(std::size_t)));
  append(h, static_cast<std::uint16_t>(1));  // endianness probe
  return h;
}

}  // namespace

StateWriter::StateWriter() : out_(header()) {}

void StateWriter::record(const std::string& name, std::size_t element_size, std::size_t count, const void* data) {
  append(out_, static_cast<std::uint32_t>(name.size()));
  out_.append(name);
  append(out_, static_cast<std::uint64_t>(element_size));
  append(out_, static_cast<std::uint64_t>(count));
  out_.append(static_cast<const char*>(data), element_size * count);
}

StateReader::StateReader(std::string bytes, std::string source) : bytes_(std::move(bytes)), source_(std::move(source)) {
  const std::string h = header();
  if (bytes_.size() < h.size() || bytes_.compare(0, sizeof kMagic, kMagic, sizeof kMagic) != 0)
    throw InputError(source_, "", "not a sloshsph checkpoint (bad header)");
  if (bytes_.compare(0, h.size(), h) != 0)
    throw InputError(source_, "", "the checkpoint was written on a machine with other number formats");
  position_ = h.size();
}

std::size_t StateReader::expect(const std::string& name, std::size_t element_size) {
  std::uint32_t length = 0;
  take(&length, sizeof length, name);
  if (length > 256 || position_ + length > bytes_.size()) fail(name, "damaged record header");
  const std::string found = bytes_.substr(position_, length);
  position_ += length;
  if (found != name) fail(name, "found record '" + found + "' instead (written by another version?)");
  std::uint64_t size = 0, count = 0;
  take(&size, sizeof size, name);
  take(&count, sizeof count, name);
  if (size != element_size) fail(name, "element size " + std::to_string(size) + ", expected " + std::to_string(element_size));
  if (count > (bytes_.size() - position_) / (size ? size : 1)) fail(name, "truncated");
  return static_cast<std::size_t>(count);
}

void StateReader::take(void* out, std::size_t n, const std::string& name) {
  if (position_ + n > bytes_.size()) fail(name, "truncated");
  if (n == 0) return;  // an empty array's data() may be null: memcpy(nullptr, ..., 0) is UB (UBSan)
  std::memcpy(out, bytes_.data() + position_, n);
  position_ += n;
}

bool StateReader::next_is(const std::string& name) const {
  std::uint32_t length = 0;
  if (position_ + sizeof length > bytes_.size()) return false;
  std::memcpy(&length, bytes_.data() + position_, sizeof length);
  return length == name.size() && position_ + sizeof length + length <= bytes_.size() &&
         bytes_.compare(position_ + sizeof length, length, name) == 0;
}

std::string StateReader::text(const std::string& name) {
  const std::size_t count = expect(name, 1);
  std::string s(count, '\0');
  take(s.data(), count, name);
  return s;
}

void StateReader::fail(const std::string& name, const std::string& what) const {
  throw InputError(source_, "", "checkpoint record '" + name + "': " + what);
}

}  // namespace sloshsph
