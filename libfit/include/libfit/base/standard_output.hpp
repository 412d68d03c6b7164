// Standard output as part of a command's output: checked before the files are switched in (docs/cli.md).
#pragma once

namespace metalfit {

// Before an output file or folder is switched in: flushes what the command printed on stdout (the paths it is about
// to write, its summary) and throws InputError ("standard output: cannot write: …") when any of it was lost, so that
// a command whose stdout fails writes nothing. finish_standard_output (errors.hpp) then prints nothing more.
void flush_standard_output();

}  // namespace metalfit
