#include "segslam/synth/sequence.h"

#include <random>
#include <stdexcept>

#include "segslam/synth/camera_path.h"

namespace segslam::synth {

namespace {

const SynthOptions& validated(const SynthOptions& options) {
  validateOptions(options);
  return options;
}

// Depth noise of each frame has its own seed, so frames do not depend on each other.
std::uint64_t noiseSeed(std::uint32_t seed, int frame) {
  std::seed_seq sequence{seed, static_cast<std::uint32_t>(frame), 0xde97u};
  std::uint32_t words[2];
  sequence.generate(words, words + 2);
  return (static_cast<std::uint64_t>(words[0]) << 32) | words[1];
}

}  // namespace

SyntheticSequence::SyntheticSequence(const SynthOptions& options)
    : options_(validated(options)),
      camera_(synthCamera(options_)),
      poses_(cameraTrajectory(options_)),
      scene_(options_),
      depth_noise_(depthNoiseFromName(options_.depth_noise)) {}

FrameImages SyntheticSequence::renderFrame(int frame) const {
  if (frame < 0 || frame >= frameCount()) throw std::out_of_range("SyntheticSequence::renderFrame");
  return synth::renderFrame(scene_.renderSceneAt(frame), camera_, poses_[frame], depth_noise_,
                            noiseSeed(options_.seed, frame));
}

}  // namespace segslam::synth
