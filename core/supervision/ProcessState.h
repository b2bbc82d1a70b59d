// The supervision state of one module process, as the watchdog reports it (Watchdog.idl).
#pragma once

namespace rgnav {

// Stopped: not running and not wanted (or not started yet). Starting: running, no ping answered
// yet. Running: answers pings. Hung: killed for missed pings, exit pending. Backoff: waiting to
// be restarted. Fatal: too many restarts, stays down until an operator starts it.
enum class ProcessState { Stopped, Starting, Running, Hung, Backoff, Fatal };

}  // namespace rgnav
