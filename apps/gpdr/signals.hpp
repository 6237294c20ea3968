#pragma once
// What gpdr does when it is told to stop: on SIGINT, SIGTERM or SIGHUP it
// removes the temporary files of the output it is writing (so a killed run
// leaves the folder as it found it: earlier results intact, nothing hidden
// added), then dies of the same signal, so that its caller sees how it
// ended (a shell reports exit status 128 + the signal's number).

namespace gpdr::app {

void remove_temporaries_on_signals();

}  // namespace gpdr::app
