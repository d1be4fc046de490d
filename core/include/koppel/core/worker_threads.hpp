// The one way koppel spreads work over threads (the atlas, motion, path and fit synthesis, the
// tolerance Monte Carlo run, design charts): `work` pulls its items from a shared counter until
// none is left, so any number of threads finishes all of it.
#pragma once

#include <functional>

namespace koppel {

// Runs `work` on `wanted` threads (0: one per core, at most kMaxThreads), the calling thread
// among them. A thread that cannot be created (std::system_error: no memory for its stack,
// a process limit) is not an error: the work runs on the threads there are, at least this one.
// Under an address-space limit (ulimit -v) the threads are at most as many as their stacks fit
// in a quarter of it, and malloc keeps to one arena per core (glibc's 64 MB arenas would take it).
// An exception thrown by `work` on any thread is rethrown here once every thread has joined (the
// first, when several throw): the threads that did not throw finish what they pulled first.
// Returns the number of threads that ran. Precondition: 0 <= wanted <= kMaxThreads.
int RunOnThreads(int wanted, const std::function<void()>& work);

}  // namespace koppel
