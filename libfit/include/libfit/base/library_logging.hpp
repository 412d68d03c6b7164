// What the libraries under libfit print (docs/cli.md, "Messages"): Ceres' glog output is silenced (its solver
// reports are read from the summary; a failed residual evaluation is a result, not a message), and OpenColorIO's
// log goes through one function that prints each message as "<program>: warning: OCIO: …" on one sanitised line.
#pragma once

namespace metalfit {

// Call once, first thing in main. `program` must outlive the process ("metalfit", "glpreview").
void route_library_logging(const char* program);

}  // namespace metalfit
