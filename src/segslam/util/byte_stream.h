#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

namespace segslam::util {

// FNV-1a, 64 bits: the checksum of binary files of our own (not cryptographic; it catches
// truncation, bit flips and edits).
std::uint64_t fnv1a64(std::string_view bytes);

// Little-endian serialisation, independent of the host's byte order.
class ByteWriter {
 public:
  void putU8(std::uint8_t value) { putUnsigned(value, 1); }
  void putU32(std::uint32_t value) { putUnsigned(value, 4); }
  void putU64(std::uint64_t value) { putUnsigned(value, 8); }
  void putI32(std::int32_t value) { putU32(static_cast<std::uint32_t>(value)); }
  void putF32(float value);
  void putF64(double value);
  void putBytes(const void* data, std::size_t size);
  // Length (u32) and bytes.
  void putString(std::string_view text);
  [[nodiscard]] const std::string& bytes() const { return bytes_; }

 private:
  void putUnsigned(std::uint64_t value, std::size_t size);

  std::string bytes_;
};

// Reads what ByteWriter wrote. Reading past the end throws Error naming `file` ("truncated ...").
class ByteReader {
 public:
  ByteReader(std::string_view bytes, std::filesystem::path file, std::string what);

  std::uint8_t getU8() { return static_cast<std::uint8_t>(getUnsigned(1)); }
  std::uint32_t getU32() { return static_cast<std::uint32_t>(getUnsigned(4)); }
  std::uint64_t getU64() { return getUnsigned(8); }
  std::int32_t getI32() { return static_cast<std::int32_t>(getU32()); }
  float getF32();
  double getF64();
  void getBytes(void* out, std::size_t size);
  std::string getString();
  // A count of records of at least `min_record_bytes` each: one larger than what is left is
  // corruption, caught before anything is allocated for it.
  std::size_t getCount(std::size_t min_record_bytes);
  [[nodiscard]] std::size_t remaining() const { return bytes_.size() - offset_; }
  [[noreturn]] void fail(const std::string& message) const;

 private:
  std::uint64_t getUnsigned(std::size_t size);
  const char* take(std::size_t size);

  std::string_view bytes_;
  std::filesystem::path file_;
  std::string what_;
  std::size_t offset_ = 0;
};

}  // namespace segslam::util
