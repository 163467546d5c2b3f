#include "segslam/util/thread_priority.h"

#include <sys/resource.h>
#include <unistd.h>

#include <ctime>

namespace segslam::util {

void lowerThisThreadsPriority(int niceness) {
  if (niceness > 0) setpriority(PRIO_PROCESS, static_cast<id_t>(gettid()), niceness);
}

double thisThreadCpuSeconds() {
  timespec now{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
  return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}

}  // namespace segslam::util
