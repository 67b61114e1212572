// SPDX-License-Identifier: LGPL-2.1-or-later
#include "FeatureLines/support/IdleThreads.h"

#include <omp.h>

namespace featurelines {

int threadCount(int requested)
{
    return requested > 0 ? requested : omp_get_max_threads();
}

void releaseIdleThreads()
{
    // OpenMP 5.0; inside a parallel region it fails without effect.
    omp_pause_resource_all(omp_pause_soft);
}

} // namespace featurelines
