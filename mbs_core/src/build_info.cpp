#include "kegel/core/build_info.hpp"

#include <Eigen/Core>
#include <sundials/sundials_version.h>

namespace kegel {

std::string core_version() { return KEGEL_VERSION; }

std::string eigen_version() {
  return std::to_string(EIGEN_WORLD_VERSION) + "." + std::to_string(EIGEN_MAJOR_VERSION) + "." +
         std::to_string(EIGEN_MINOR_VERSION);
}

std::string sundials_version() {
  char buf[64] = {0};
  if (SUNDIALSGetVersion(buf, static_cast<int>(sizeof(buf))) != 0) return KEGEL_SUNDIALS_VERSION;
  return std::string(buf);
}

}  // namespace kegel
