#include "app/distributed/mpi_launch.h"

#include <cstdlib>
#include <initializer_list>

namespace candela {

bool launchedByMpi() {
  for (const char* variable : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK", "PMI_SIZE"})
    if (std::getenv(variable)) return true;
  return false;
}

}  // namespace candela
