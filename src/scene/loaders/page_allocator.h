#pragma once
#include <sys/mman.h>

#include <cstddef>
#include <new>
#include <vector>

namespace candela {

// An allocator that takes whole pages from the system and gives them back when freed. The heap keeps freed
// memory for later use instead, and for the many mid-sized arrays that a parallel parse fills and then drops
// that adds up to hundreds of megabytes of resident memory holding nothing.
template <class T>
struct PageAllocator {
  using value_type = T;

  PageAllocator() = default;
  template <class U>
  PageAllocator(const PageAllocator<U>&) {}

  T* allocate(size_t n) {
    void* p = ::mmap(nullptr, n * sizeof(T), PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (p == MAP_FAILED) throw std::bad_alloc();
    return static_cast<T*>(p);
  }
  void deallocate(T* p, size_t n) { ::munmap(p, n * sizeof(T)); }

  template <class U>
  bool operator==(const PageAllocator<U>&) const {
    return true;
  }
};

template <class T>
using PageVector = std::vector<T, PageAllocator<T>>;

}  // namespace candela
