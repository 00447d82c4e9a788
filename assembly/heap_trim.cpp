#include "assembly/heap_trim.hpp"

#include <cstdlib>  // defines __GLIBC__ under glibc, tested below
#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace pc {

void return_free_heap_pages() {
#if defined(__GLIBC__)
  malloc_trim(0);
#endif
}

}  // namespace pc
