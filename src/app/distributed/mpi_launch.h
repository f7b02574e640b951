#pragma once

namespace candela {

// Whether this process was started by an MPI launcher (mpirun, mpiexec, srun with PMI/PMIx), judged by the
// environment it sets, so that a plain start never initialises MPI, and a build without MPI can say so.
bool launchedByMpi();

}  // namespace candela
