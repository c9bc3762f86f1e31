#pragma once
// GLSL's `if (condition) ... else ...` for a value-returning branch. With
// double and float the condition is a bool (or, while a path is replayed,
// the recorded outcome: oracle/branch_paths.h); with Interval it is a Truth,
// and when it is Unknown an implementation may take either way: on a path
// of the active explorer each way is its own alternative, without one the
// result is the hull of both.
#include <concepts>

#include "oracle/branch_paths.h"
#include "oracle/interval.h"

namespace snell::glsl {

template <class Then, class Else>
auto branch(bool condition, Then then, Else otherwise) {
  if (BranchReplay* replay = activeBranchReplay())
    condition = replay->next();
  else if (RecordBranches* record = activeBranchRecord())
    record->record(condition);
  return condition ? then() : otherwise();
}

template <class Then, class Else>
auto branch(Truth condition, Then then, Else otherwise) {
  BranchPaths* paths = activeBranchPaths();
  bool tookThen = condition == Truth::True;
  if (condition == Truth::Unknown) {
    const BranchPaths::Choice choice = paths ? paths->chooseUnknown() : BranchPaths::Choice::Hull;
    if (choice == BranchPaths::Choice::Hull) return hull(then(), otherwise());
    tookThen = choice == BranchPaths::Choice::Then;
  }
  if (paths) paths->record(tookThen);
  return tookThen ? then() : otherwise();
}

}  // namespace snell::glsl
