#include "radiant/server/job_store.h"

namespace radiant::server {

std::string attempts_exhausted_error(int max_attempts) {
    return "its solve was started " + std::to_string(max_attempts) +
           " times and each time its radiantd died before it finished (killed, most likely for "
           "running out of memory); it is not run again";
}

}  // namespace radiant::server
