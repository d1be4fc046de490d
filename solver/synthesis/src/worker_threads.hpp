// The one way synthesis spreads work over threads (atlas, motion, path, fit): `work` pulls its
// items from a shared counter until none is left, so any number of threads finishes all of it.
// Private to the synthesis library.
#pragma once

#include <functional>

namespace koppel {

// Runs `work` on `wanted` threads (0: one per core, at most kMaxThreads), the calling thread
// among them. A thread that cannot be created (std::system_error: no memory for its stack,
// a process limit) is not an error: the work runs on the threads there are, at least this one.
// Returns the number of threads that ran. Precondition: 0 <= wanted <= kMaxThreads.
int RunOnThreads(int wanted, const std::function<void()>& work);

}  // namespace koppel
