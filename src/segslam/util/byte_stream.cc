#include "segslam/util/byte_stream.h"

#include <bit>
#include <cstring>

#include "segslam/util/error.h"

namespace segslam::util {

std::uint64_t fnv1a64(std::string_view bytes) {
  std::uint64_t hash = 0xcbf29ce484222325ULL;
  for (const char c : bytes) {
    hash ^= static_cast<unsigned char>(c);
    hash *= 0x100000001b3ULL;
  }
  return hash;
}

void ByteWriter::putUnsigned(std::uint64_t value, std::size_t size) {
  for (std::size_t i = 0; i < size; ++i) {
    bytes_.push_back(static_cast<char>((value >> (8 * i)) & 0xFF));
  }
}

void ByteWriter::putF32(float value) { putU32(std::bit_cast<std::uint32_t>(value)); }

void ByteWriter::putF64(double value) { putU64(std::bit_cast<std::uint64_t>(value)); }

void ByteWriter::putBytes(const void* data, std::size_t size) {
  if (size == 0) return;  // data may be null (an empty cv::Mat)
  bytes_.append(static_cast<const char*>(data), size);
}

void ByteWriter::putString(std::string_view text) {
  putU32(static_cast<std::uint32_t>(text.size()));
  putBytes(text.data(), text.size());
}

ByteReader::ByteReader(std::string_view bytes, std::filesystem::path file, std::string what)
    : bytes_(bytes), file_(std::move(file)), what_(std::move(what)) {}

std::uint64_t ByteReader::getUnsigned(std::size_t size) {
  const char* data = take(size);
  std::uint64_t value = 0;
  for (std::size_t i = 0; i < size; ++i) {
    value |= static_cast<std::uint64_t>(static_cast<unsigned char>(data[i])) << (8 * i);
  }
  return value;
}

float ByteReader::getF32() { return std::bit_cast<float>(getU32()); }

double ByteReader::getF64() { return std::bit_cast<double>(getU64()); }

void ByteReader::getBytes(void* out, std::size_t size) {
  const char* data = take(size);
  // An empty buffer (an empty cv::Mat) may have no address: memcpy must not see it.
  if (size > 0) std::memcpy(out, data, size);
}

std::string ByteReader::getString() {
  const std::size_t size = getCount(1);
  return std::string(take(size), size);
}

std::size_t ByteReader::getCount(std::size_t min_record_bytes) {
  const std::uint32_t count = getU32();
  if (static_cast<std::uint64_t>(count) * min_record_bytes > remaining()) {
    fail("a count of " + std::to_string(count) + " records at offset " +
         std::to_string(offset_ - 4) + " is larger than the rest of the file");
  }
  return count;
}

void ByteReader::fail(const std::string& message) const {
  failAt(file_, "corrupt " + what_ + ": " + message);
}

const char* ByteReader::take(std::size_t size) {
  if (size > remaining()) {
    failAt(file_, "truncated " + what_ + " (" + std::to_string(bytes_.size()) +
                      " bytes, needs more at offset " + std::to_string(offset_) + ")");
  }
  const char* data = bytes_.data() + offset_;
  offset_ += size;
  return data;
}

}  // namespace segslam::util
