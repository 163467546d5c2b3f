#include "segslam/util/byte_stream.h"

#include <gtest/gtest.h>

#include "segslam/util/error.h"

namespace segslam::util {
namespace {

TEST(ByteStream, ReadsBackWhatWasWrittenLittleEndian) {
  ByteWriter out;
  out.putU32(0x01020304);
  out.putU64(0x1122334455667788ULL);
  out.putI32(-5);
  out.putF64(0.1);
  out.putF32(2.5f);
  out.putString("segslam");
  EXPECT_EQ(out.bytes()[0], 0x04);
  ByteReader in(out.bytes(), "f.bin", "test file");
  EXPECT_EQ(in.getU32(), 0x01020304U);
  EXPECT_EQ(in.getU64(), 0x1122334455667788ULL);
  EXPECT_EQ(in.getI32(), -5);
  EXPECT_EQ(in.getF64(), 0.1);
  EXPECT_EQ(in.getF32(), 2.5f);
  EXPECT_EQ(in.getString(), "segslam");
  EXPECT_EQ(in.remaining(), 0U);
}

TEST(ByteStream, ReadingPastTheEndNamesTheFile) {
  ByteWriter out;
  out.putU32(7);
  ByteReader in(out.bytes(), "short.bin", "test file");
  EXPECT_EQ(in.getU32(), 7U);
  try {
    in.getU8();
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("short.bin: truncated test file"), std::string::npos);
  }
}

TEST(ByteStream, ACountLargerThanTheRestIsCorruption) {
  ByteWriter out;
  out.putU32(1000);
  ByteReader in(out.bytes(), "count.bin", "test file");
  EXPECT_THROW(in.getCount(8), Error);
}

TEST(ByteStream, Fnv1a64MatchesTheReferenceValues) {
  EXPECT_EQ(fnv1a64(""), 0xcbf29ce484222325ULL);
  EXPECT_EQ(fnv1a64("a"), 0xaf63dc4c8601ec8cULL);
}

}  // namespace
}  // namespace segslam::util
