#pragma once
// Run by root, the grader runs each program as a user of its own: an
// unused user id that keeps only the right to read and search every file
// (CAP_DAC_READ_SEARCH, so that a program under /root still runs and reads
// its own files). Root is exempt from RLIMIT_NPROC; a user of its own is
// not, and it holds no other process, so the limit counts the program's
// tasks alone. It cannot signal the grader or any other user's process,
// nor write outside its directory and what any user may write, and what
// it leaves running is found by its user id.
//
// Docker's default capabilities leave out CAP_DAC_READ_SEARCH; there the
// program keeps CAP_DAC_OVERRIDE instead, so that it still reaches its
// files, and may then also write where root may.

#include <sys/types.h>

#include <optional>
#include <string>

namespace simcheck {

// Whether this process can: it is root, may change users and read every
// file, and the user ids it would give are mapped in its user namespace.
bool can_run_as_own_users();

// The capability a program run as a user of its own keeps:
// CAP_DAC_READ_SEARCH, or CAP_DAC_OVERRIDE where that is missing.
int kept_capability();

// A user id that no process, passwd or group entry uses and no other run
// holds, or nothing when none is left. Safe from any thread.
std::optional<uid_t> claim_own_user();

// Gives `user` back for another run, unless a process of it is still
// there (one stuck in the kernel): it then stays claimed.
void release_own_user(uid_t user);

// Removes what `user` made in the places any user may write (/tmp,
// /var/tmp, /dev/shm, and $TMPDIR): each entry there that it owns, whole,
// but `keep` (its working directory, removed by its owner). Returns how
// many entries.
int remove_files_of(uid_t user, const std::string& keep);

// In a child between fork and exec (async-signal-safe calls only): becomes
// `user`, group `user` and no supplementary groups, with `capability`
// (kept_capability()) through exec and no way to gain more (no new
// privileges: a set-user-ID program runs as the user). False if any step
// fails.
bool become_own_user(uid_t user, int capability);

}  // namespace simcheck
