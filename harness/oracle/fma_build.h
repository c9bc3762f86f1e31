#pragma once
// The oracle's hottest roads (oracle/point_builtins.h, and a built-in
// call's exact and fp32 evaluations) are compiled twice on x86: once for
// any CPU of the architecture, where each error-free product (std::fma) is
// a call into libm, and once for CPUs with fused multiply-add
// instructions, where it is one instruction and the road needs a sixth
// fewer instructions in all. The library is built with -ffp-contract=off,
// so the second build does the same IEEE operations as the first and gives
// the same bits (tests/oracle/point_builtins_test.cpp holds each against the general road).
namespace snell {

enum class OracleBuild { Portable, Fma };

#if defined(__GNUC__) && (defined(__x86_64__) || defined(__i386__))
#define SNELL_ORACLE_FMA_BUILD 1
#else
#define SNELL_ORACLE_FMA_BUILD 0
#endif

// Whether this CPU runs the Fma build.
inline bool cpuHasFmaInstructions() {
#if SNELL_ORACLE_FMA_BUILD
  static const bool has = __builtin_cpu_supports("fma");
  return has;
#else
  return false;
#endif
}

// The build a call takes unless told: Fma where the CPU has it.
inline OracleBuild fastestOracleBuild() {
  return cpuHasFmaInstructions() ? OracleBuild::Fma : OracleBuild::Portable;
}

}  // namespace snell
