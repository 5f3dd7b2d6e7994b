#pragma once
// Stop requests by signal: SIGTERM, SIGUSR1 (Slurm's warning before the time limit) and SIGINT
// ask a campaign to stop cleanly (samples in flight finish, the journal is kept, exit 75).
namespace pound {

/// Installs handlers so that SIGTERM, SIGUSR1 and SIGINT request a clean stop, and ignores
/// SIGXFSZ (a file size limit is then a failed write). Call it before MPI_Init: a request that
/// comes while the ranks start is then kept and honoured once the campaign runs.
void install_stop_handlers();
/// True once a stop signal came (SIGTERM, SIGUSR1, SIGINT). A failed write of the journal
/// stops only the run it happened in, not a later run_campaign of the same process.
bool stop_requested();

}  // namespace pound
