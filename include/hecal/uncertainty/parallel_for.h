// Runs body(0), …, body(count − 1) on up to `threads` threads (0: every core), each index once,
// in no particular order; the calling thread works too. The first exception thrown by a body
// stops the remaining indices from starting and is rethrown after every thread has joined.
// Bodies must write only to their own slots (results indexed by i), so results do not depend
// on the number of threads.
#pragma once

#include <functional>

namespace hecal::uncertainty {

void ParallelFor(int count, int threads, const std::function<void(int)>& body);

}  // namespace hecal::uncertainty
