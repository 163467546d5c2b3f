#pragma once

#include <optional>

namespace segslam::segmentation {

// How much of its wall-clock time a thread spends computing rather than waiting (for a camera's
// next frame, for a queue). A tracking thread that never waits has no CPU to spare for
// background work such as a segmentation network: whatever that work takes slows tracking down.
class BusyShare {
 public:
  // `smoothing`: weight of the newest interval in the running share (0..1].
  explicit BusyShare(double smoothing = 0.2);

  // Records the thread's CPU time and the wall-clock time now (seconds, any common origin): the
  // end of an interval that counts, and the start of the next.
  void sample(double cpu_seconds, double wall_seconds);
  // Starts a new interval without counting the time since the last sample (e.g. time the
  // thread spent waiting on the very work whose share is being decided).
  void restart(double cpu_seconds, double wall_seconds);

  // Share of the wall-clock time between samples that the thread spent on the CPU, smoothed over
  // the last intervals; 0 until two samples are in.
  [[nodiscard]] double value() const { return share_.value_or(0.0); }

 private:
  struct Sample {
    double cpu_seconds;
    double wall_seconds;
  };

  double smoothing_;
  std::optional<Sample> last_;
  std::optional<double> share_;
};

}  // namespace segslam::segmentation
