// Reading a CAD file in a forked child process, so that OpenCASCADE's readers
// cannot take the host down: a segfault, an endless loop or a runaway
// allocation on a malformed file becomes an InputError naming the file.
//
// The child runs the whole reading step (translation, sewing, healing, the
// validity check) under a limit on its CPU time (watched by the parent; the
// kernel's RLIMIT_CPU backs it up), a much longer wall-clock limit for a child
// that waits without computing, and an address-space limit (not under AddressSanitizer, which
// reserves terabytes of virtual memory), with its stdout and stderr on /dev/null, and hands back
// the shape in OpenCASCADE's binary format (BinTools, exact to the bit) with the solid names (by
// index in TopExp_Explorer(shape, TopAbs_SOLID) order, which the format keeps), the log lines, or
// the InputError it raised. It ends with _exit: no atexit handler, no flush of the stdio buffers it
// inherited. The parent kills and reaps the child on every path.
#pragma once

#include <functional>
#include <string>

#include "cad_model.h"

namespace rdmesh::cad {

/// Runs `read` (which may throw InputError) in a child process under the
/// limits of `options` and returns its shape. `format` ("STEP", "IGES",
/// "BREP") names the reader in the errors: "cannot read the file: the STEP
/// reader crashed (malformed file?)", "... did not finish within 60 s of computing", "...
/// ran out of memory". Where fork() is unavailable or fails, `read` runs in
/// this process.
ReadShape read_in_child(const std::string& path, const std::string& format,
                        const std::function<ReadShape()>& read, const CadOptions& options);

/// The CPU seconds reading `path` may take, at most 1e9: the option's
/// when positive, else 10 s plus 20 s per MB of the file, in whole seconds
/// (reading a 1 MB STEP assembly, sewing and checking it takes about 5 s; a
/// 3 kB mutant of a BREP file looped in OpenCASCADE's reader for the whole
/// minute the limit once was). Preparing the read model (build_model) gets three
/// times as long.
double read_time_limit_seconds(const CadOptions& options, const std::string& path);

}  // namespace rdmesh::cad
