#include "segslam/synth/synth_options.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "segslam/util/error.h"

namespace segslam::synth {
namespace {

// Expects validateOptions to reject the default options changed by `change`, naming `option`.
void expectRejected(const std::function<void(SynthOptions&)>& change, const std::string& option) {
  SynthOptions options;
  change(options);
  try {
    validateOptions(options);
    FAIL() << "expected util::Error mentioning " << option;
  } catch (const util::Error& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find(option), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
}

TEST(SynthOptions, DefaultsAreValidAndMatchTheDocumentedCamera) {
  const SynthOptions options;
  EXPECT_NO_THROW(validateOptions(options));
  EXPECT_EQ(options.frames, 300);
  EXPECT_EQ(options.people, 2);
  const core::Camera camera = synthCamera(options);
  EXPECT_EQ(camera.width, 640);
  EXPECT_EQ(camera.height, 480);
  EXPECT_DOUBLE_EQ(camera.fx, 525.0);
  EXPECT_DOUBLE_EQ(camera.fy, 525.0);
  EXPECT_DOUBLE_EQ(camera.cx, 319.5);
  EXPECT_DOUBLE_EQ(camera.cy, 239.5);
  EXPECT_DOUBLE_EQ(camera.depth_factor, 5000.0);
  EXPECT_DOUBLE_EQ(camera.fps, 30.0);
  EXPECT_FALSE(camera.hasDistortion());
}

TEST(SynthOptions, IntrinsicsScaleWithTheWidth) {
  SynthOptions options;
  options.width = 320;
  options.height = 240;
  const core::Camera camera = synthCamera(options);
  EXPECT_DOUBLE_EQ(camera.fx, 262.5);
  EXPECT_DOUBLE_EQ(camera.cx, 159.5);
  EXPECT_DOUBLE_EQ(camera.cy, 119.5);
}

TEST(SynthOptions, TimestampsStartAtTheFixedEpochAndStepByOneThirtieth) {
  EXPECT_DOUBLE_EQ(frameTimestamp(0), 1700000000.0);
  EXPECT_NEAR(frameTimestamp(30), 1700000001.0, 1e-6);
}

TEST(SynthOptions, RejectsImpossibleOptionsWithOneLineNamingTheOption) {
  expectRejected([](SynthOptions& o) { o.frames = 0; }, "--frames");
  expectRejected([](SynthOptions& o) { o.frames = -3; }, "--frames");
  expectRejected([](SynthOptions& o) { o.width = 8; }, "--width");
  expectRejected([](SynthOptions& o) { o.height = 0; }, "--height");
  expectRejected([](SynthOptions& o) { o.path = "spiral"; }, "--path");
  expectRejected([](SynthOptions& o) { o.depth_noise = "loud"; }, "--depth-noise");
  expectRejected([](SynthOptions& o) { o.people = -1; }, "--people");
  expectRejected([](SynthOptions& o) { o.people = kSynthMaxPeople + 1; }, "--people");
  expectRejected([](SynthOptions& o) { o.person_speed = -0.5; }, "--person-speed");
  expectRejected([](SynthOptions& o) { o.person_speed = std::nan(""); }, "--person-speed");
  expectRejected([](SynthOptions& o) { o.person_size = 0.0; }, "--person-size");
  expectRejected(
      [](SynthOptions& o) {
        o.path = "loop";
        o.frames = kSynthMinLoopFrames - 1;
      },
      "--path loop");
  expectRejected([](SynthOptions& o) { o.laps = 0; }, "--laps");
  expectRejected(
      [](SynthOptions& o) {
        o.path = "room";
        o.laps = 2;
        o.frames = 2 * kSynthMinLoopFrames - 1;
      },
      "--path room");
}

TEST(SynthOptions, AcceptsTheEdgesOfTheRanges) {
  SynthOptions options;
  options.people = 0;
  options.person_speed = 0.0;
  options.frames = 1;
  options.width = kSynthMinWidth;
  options.height = kSynthMinHeight;
  EXPECT_NO_THROW(validateOptions(options));
  options.path = "loop";
  options.frames = kSynthMinLoopFrames;
  options.depth_noise = "kinect";
  EXPECT_NO_THROW(validateOptions(options));
}

}  // namespace
}  // namespace segslam::synth
