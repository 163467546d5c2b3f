#pragma once

namespace segslam::util {

// Raises the calling thread's niceness (Linux schedules threads individually), so that a
// background thread takes only the CPU time the others leave. 0 or less: unchanged.
void lowerThisThreadsPriority(int niceness);

// CPU time the calling thread has used, seconds: unlike wall time it does not grow while the
// thread waits for a busy machine.
double thisThreadCpuSeconds();

}  // namespace segslam::util
