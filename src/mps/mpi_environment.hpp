// MPI start-up for the libraries that need it (hypre). A serial run initialises MPI as a singleton on
// first use and finalises it at exit; a run under mpirun finds it already initialised.
#pragma once

namespace mistfall {

void ensureMpiInitialized();

}  // namespace mistfall
