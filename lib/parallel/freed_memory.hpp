#pragma once
// Giving memory the program has freed back to the system.
//
// glibc keeps freed memory mapped in its arenas (one per thread that
// allocated: the refining threads have their own) for later requests.  The
// mesh's tables are not allocated from the arenas (mesh/reserved_table.hpp),
// so while the mesh grows, freed queue storage that the queues do not ask
// for again only adds to the resident size: at the end of the graded pipe's
// -j2 refinement, about 50 MiB of it on top of what was in use.

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace gpdr::parallel {

// Returns the free memory of every arena to the system (whole pages; a
// call costs about a millisecond with a few hundred megabytes allocated).
inline void return_freed_memory() {
#if defined(__GLIBC__)
    malloc_trim(0);
#endif
}

}  // namespace gpdr::parallel
