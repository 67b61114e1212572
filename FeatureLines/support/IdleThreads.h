// SPDX-License-Identifier: LGPL-2.1-or-later
// OpenMP's idle worker threads let go before the pipeline's serial steps, so that their spinning
// takes no CPU time from other work. Design: docs/design/pipeline.md (Support).
#pragma once

namespace featurelines {

/// Lets the idle OpenMP worker threads of the calling thread go before a serial step of a few
/// milliseconds or more (a sort, a flood fill over the 1-rings); the next parallel loop starts
/// them again. Does nothing inside a parallel region.
void releaseIdleThreads();

} // namespace featurelines
