#pragma once
// SIGINT and SIGTERM do not kill simcli mid-write: they set a flag that the
// run checks after every step, so that it can stop cleanly (flush, write a
// checkpoint, remove an unfinished output) and exit 128 + the signal.

namespace simcli {

void catch_interrupts();
// The signal received (SIGINT or SIGTERM), or 0.
int pending_interrupt();

}  // namespace simcli
