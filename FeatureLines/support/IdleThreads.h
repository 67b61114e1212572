// SPDX-License-Identifier: LGPL-2.1-or-later
// OpenMP's idle worker threads during the serial steps of the pipeline.
#pragma once

namespace featurelines {

/// Lets the idle OpenMP worker threads of the calling thread go before a serial step of a few
/// milliseconds or more (a sort, a flood fill over the 1-rings). After a parallel loop libgomp's
/// workers spin for about 7 ms before they sleep (OMP_WAIT_POLICY unset), and on a machine
/// shared with other work that spinning is CPU time taken from it; the next parallel loop starts
/// them again, which costs about 0.1 ms. Does nothing inside a parallel region.
void releaseIdleThreads();

} // namespace featurelines
