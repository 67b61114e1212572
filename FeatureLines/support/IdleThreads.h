// SPDX-License-Identifier: LGPL-2.1-or-later
// OpenMP's worker threads: how many a stage runs on, and the idle ones let go before the
// pipeline's serial steps, so that their spinning takes no CPU time from other work.
// Design: docs/design/pipeline.md (Support).
#pragma once

namespace featurelines {

/// The worker threads of a stage whose options ask for `requested`: that many when above 0,
/// else OpenMP's default.
int threadCount(int requested);

/// Lets the idle OpenMP worker threads of the calling thread go before a serial step of a few
/// milliseconds or more (a sort, a flood fill over the 1-rings); the next parallel loop starts
/// them again. Does nothing inside a parallel region.
void releaseIdleThreads();

} // namespace featurelines
