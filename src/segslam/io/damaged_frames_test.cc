#include "segslam/io/damaged_frames.h"

#include <gtest/gtest.h>

#include "segslam/io/io_test_support.h"

namespace segslam::io {
namespace {

using testing::errorMessage;

TEST(DamagedFrames, EachSkippedFrameIsWarnedAndCounted) {
  testing::CapturedLog log;
  DamagedFrames damaged("d/seq", 4);
  damaged.skip(1, 1305031102.5, "d/seq/rgb/1.jpg: damaged image: cut short");
  damaged.skip(3, 1305031102.6, "d/seq/depth/3.png: damaged image: cut short");
  EXPECT_EQ(damaged.count(), 2u);
  EXPECT_EQ(log.text(),
            "[warning] frame 1 (1305031102.500000) skipped: d/seq/rgb/1.jpg: damaged image: cut "
            "short\n[warning] frame 3 (1305031102.600000) skipped: d/seq/depth/3.png: damaged "
            "image: cut short\n");
}

TEST(DamagedFrames, MoreThanHalfDamagedStopsTheSequenceNamingIt) {
  DamagedFrames damaged("d/seq", 5);
  damaged.skip(0, 1.0, "first damage");
  damaged.skip(1, 2.0, "second damage");
  EXPECT_EQ(errorMessage([&] { damaged.skip(2, 3.0, "third damage"); }),
            "d/seq: more than half of the 5 frames have damaged images (3 so far; the first: "
            "first damage)");
}

}  // namespace
}  // namespace segslam::io
