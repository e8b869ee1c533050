// Versions of kegel's core and of the libraries it was built against, written next to every
// result for reproducibility.
#pragma once

#include <string>

namespace kegel {

std::string core_version();
std::string eigen_version();
std::string sundials_version();  ///< as reported by the linked SUNDIALS library at run time

}  // namespace kegel
