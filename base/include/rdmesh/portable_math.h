// Transcendental functions that return the same bits on every machine.
//
// glibc picks its libm routines by CPU at load time (x86-64: an FMA variant of
// acos, atan2, sin, exp... where the CPU has FMA), and the variants differ in
// the last bit on some arguments. A mesh whose decisions read those bits then
// depends on the machine: the 147 k-tet sphere came out with two md5s on one
// machine, with GLIBC_TUNABLES=glibc.cpu.hwcaps=-FMA,-AVX2 and without, in
// its final improvement, which ranks tetrahedra by acos of a cosine. The
// functions here use only +, -, *, / and sqrt, which IEEE 754 rounds exactly,
// so they give one result everywhere (their file is built without contraction
// into fused multiply-adds, which GCC does by default where the CPU has them).
#pragma once

namespace rdmesh {

/// acos(x) in radians, within a few units in the last place of the true value,
/// the same bits on every machine; x is clamped to [-1, 1] (NaN gives NaN).
double portable_acos(double x);

}  // namespace rdmesh
