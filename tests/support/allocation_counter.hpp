#pragma once
// Counts heap allocations made while a CountAllocations object is alive, by interposing the C
// allocator (glibc: the program's malloc wins over libc's; libstdc++'s operator new and Eigen's
// aligned_malloc both allocate through malloc; aligned_alloc and posix_memalign, which neither
// uses, are not counted). Include in ONE file of a test executable only. Under
// AddressSanitizer, which interposes malloc itself, counting is unavailable
// (AllocationCounting::available() is false and tests skip).
#include <atomic>
#include <cstddef>

namespace pound::test {

inline std::atomic<long> g_allocations{0};
inline std::atomic<bool> g_counting{false};

struct AllocationCounting {
#if defined(__SANITIZE_ADDRESS__) || !defined(__GLIBC__)
  static constexpr bool available() {
    return false;
  }
#else
  static constexpr bool available() {
    return true;
  }
#endif
};

/// Allocations made during the object's life: count().
class CountAllocations {
 public:
  CountAllocations() : start_(g_allocations.load()) { g_counting = true; }
  ~CountAllocations() { g_counting = false; }
  long count() const { return g_allocations.load() - start_; }

 private:
  long start_;
};

inline void count_allocation() {
  if (g_counting.load(std::memory_order_relaxed)) g_allocations.fetch_add(1);
}

}  // namespace pound::test

#if !defined(__SANITIZE_ADDRESS__) && defined(__GLIBC__)
extern "C" {
void* __libc_malloc(std::size_t);
void* __libc_calloc(std::size_t, std::size_t);
void* __libc_realloc(void*, std::size_t);

void* malloc(std::size_t n) {
  pound::test::count_allocation();
  return __libc_malloc(n);
}
void* calloc(std::size_t n, std::size_t size) {
  pound::test::count_allocation();
  return __libc_calloc(n, size);
}
void* realloc(void* p, std::size_t n) {
  pound::test::count_allocation();
  return __libc_realloc(p, n);
}
}
#endif
