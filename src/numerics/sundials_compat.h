// sundials_compat.h - the few names in which the SUNDIALS releases the core builds with (6.x and 7.x)
// differ (docs/platforms.md, "SUNDIALS 6 and 7").
#pragma once

#include <sundials/sundials_config.h>
#include <sundials/sundials_context.h>
#include <sundials/sundials_linearsolver.h>

#if SUNDIALS_VERSION_MAJOR < 6 || SUNDIALS_VERSION_MAJOR > 7
#error "UnderwaterCable builds with SUNDIALS 6.x or 7.x"
#endif

#if SUNDIALS_VERSION_MAJOR >= 7
// The communicator of a context without MPI (7.x: SUNComm, an int without MPI).
#define UC_SUN_COMM_NULL SUN_COMM_NULL
#else
#define UC_SUN_COMM_NULL nullptr  // 6.x: a void* to the communicator
#endif

namespace uc {

// Return codes of a linear solver's setup and solve (7.x unified the codes of all SUNDIALS modules).
#if SUNDIALS_VERSION_MAJOR >= 7
constexpr int kLinearSolverSuccess = SUN_SUCCESS;
constexpr int kLinearSolverUnrecoverable = SUN_ERR_EXT_FAIL;
#else
constexpr int kLinearSolverSuccess = SUNLS_SUCCESS;
constexpr int kLinearSolverUnrecoverable = SUNLS_PACKAGE_FAIL_UNREC;
#endif
// > 0: a recoverable failure (IDA retries with a smaller step); the same value in both.
constexpr int kLinearSolverSingular = SUNLS_LUFACT_FAIL;

}  // namespace uc
