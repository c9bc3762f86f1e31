#pragma once
// Keeps the memory a process frees for its own next use. A worker reads,
// draws and compares one case after another, each with buffers of a few
// megabytes (oracle results, read-backs, images). By default glibc gives
// such buffers back to the kernel when they are freed, so the next case's
// buffers are fresh pages: page faults and zeroing were a third of a warm
// run's oracle phase (perf). Kept in the heap, they are reused instead.
namespace snell {

void keepFreedMemoryForReuse();

}  // namespace snell
