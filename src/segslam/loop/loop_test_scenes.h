#pragma once

#include "segslam/synth/sequence.h"

namespace segslam::loop {

// One lap around the synthetic room without people: its last frames revisit its first.
inline synth::SynthOptions roomLapOptions() {
  synth::SynthOptions options;
  options.path = "room";
  options.people = 0;
  options.frames = 641;
  options.seed = 1;
  return options;
}

}  // namespace segslam::loop
