#include "segslam/segmentation/busy_share.h"

#include <algorithm>

namespace segslam::segmentation {

BusyShare::BusyShare(double smoothing) : smoothing_(std::clamp(smoothing, 1e-3, 1.0)) {}

void BusyShare::sample(double cpu_seconds, double wall_seconds) {
  const Sample now{cpu_seconds, wall_seconds};
  if (last_ && now.wall_seconds > last_->wall_seconds) {
    // CPU time can exceed wall time by rounding of the two clocks: a share is at most 1.
    const double interval = std::clamp(
        (now.cpu_seconds - last_->cpu_seconds) / (now.wall_seconds - last_->wall_seconds), 0.0,
        1.0);
    share_ = share_ ? (1.0 - smoothing_) * *share_ + smoothing_ * interval : interval;
  }
  last_ = now;
}

void BusyShare::restart(double cpu_seconds, double wall_seconds) {
  last_ = Sample{cpu_seconds, wall_seconds};
}

}  // namespace segslam::segmentation
