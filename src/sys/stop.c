/* A job asked to stop by a signal saves what it has converged (include/thermoslide/sys.h). The handler only
 * records the signal; the driver and the explicit procedure look at it collectively at points where every rank
 * is (a Newton iteration's convergence test, an explicit increment's reduction), so all ranks stop together,
 * through the path a failed run takes. */
#define _POSIX_C_SOURCE 200809L /* sigaction, under -std=c11 */
#include <thermoslide/sys.h>
#include <signal.h>
#include <string.h>

static volatile sig_atomic_t stop_signal = 0;
static const int             Signals[]   = {SIGUSR1, SIGTERM, SIGINT, SIGXCPU};

static void OnSignal(int sig)
{
  if (stop_signal) { /* asked twice: the default action now (terminate) */
    signal(sig, SIG_DFL);
    raise(sig);
    return;
  }
  stop_signal = sig;
}

PetscErrorCode TslStopInstall(void)
{
  struct sigaction sa;

  PetscFunctionBeginUser;
  memset(&sa, 0, sizeof(sa));
  sa.sa_handler = OnSignal;
  sa.sa_flags   = SA_RESTART;
  sigemptyset(&sa.sa_mask);
  for (size_t k = 0; k < sizeof(Signals) / sizeof(Signals[0]); k++)
    PetscCheck(!sigaction(Signals[k], &sa, NULL), PETSC_COMM_SELF, PETSC_ERR_SYS, "cannot install the handler of signal %d", Signals[k]);
  PetscFunctionReturn(PETSC_SUCCESS);
}

int TslStopLocal(void)
{
  return (int)stop_signal;
}

PetscErrorCode TslStopRequested(MPI_Comm comm, int *sig)
{
  int local = (int)stop_signal;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Allreduce(&local, sig, 1, MPI_INT, MPI_MAX, comm));
  if (*sig) stop_signal = *sig; /* every rank then reports the same signal (and exit status), whichever received it */
  PetscFunctionReturn(PETSC_SUCCESS);
}

const char *TslStopName(int sig)
{
  switch (sig) {
  case SIGUSR1:
    return "SIGUSR1";
  case SIGTERM:
    return "SIGTERM";
  case SIGINT:
    return "SIGINT";
  case SIGXCPU:
    return "SIGXCPU";
  default:
    return "a signal";
  }
}
