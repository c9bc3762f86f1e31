#include "core/heap_reuse.h"

#include <malloc.h>

namespace snell {

void keepFreedMemoryForReuse() {
  // Blocks up to 32 MiB (the largest threshold glibc accepts) come from the
  // heap, not from a mapping of their own that free() unmaps.
  mallopt(M_MMAP_THRESHOLD, 32 << 20);
  // The top of the heap is given back only once 512 MiB of it are free:
  // far above one case's working set, far below the machine's memory.
  mallopt(M_TRIM_THRESHOLD, 512 << 20);
}

}  // namespace snell
