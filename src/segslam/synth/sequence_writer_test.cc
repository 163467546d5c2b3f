#include "segslam/synth/sequence_writer.h"

#include <gtest/gtest.h>

#include <fstream>

#include "segslam/synth/synth_options.h"
#include "segslam/testing/test_support.h"
#include "segslam/util/error.h"

namespace segslam::synth {
namespace {

TEST(SynthSequenceWriter, NamesImagesByTheirSixDecimalTimestamp) {
  EXPECT_EQ(frameImagePath("rgb", frameTimestamp(0)), "rgb/1700000000.000000.png");
  EXPECT_EQ(frameImagePath("depth", frameTimestamp(1)), "depth/1700000000.033333.png");
  EXPECT_EQ(frameImagePath("mask", frameTimestamp(2)), "mask/1700000000.066667.png");
}

TEST(SynthSequenceWriter, CreatesTheImageFoldersOrSaysWhyNot) {
  const segslam::testing::ScopedTempDir dir;
  const SequenceWriter writer(dir.path() / "out");
  for (const char* kind : {"rgb", "depth", "mask", "labels", "instances"}) {
    EXPECT_TRUE(std::filesystem::is_directory(dir.path() / "out" / kind)) << kind;
  }
  std::ofstream(dir.path() / "file") << "not a folder";
  EXPECT_THROW(SequenceWriter(dir.path() / "file"), util::Error);
}

}  // namespace
}  // namespace segslam::synth
