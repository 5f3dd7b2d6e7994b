#pragma once
// Counts heap allocations made while a CountAllocations object is alive. Include in ONE file of
// a test executable only.
//   - Plain glibc builds: the program's malloc, calloc and realloc interpose libc's (libstdc++'s
//     operator new and Eigen's aligned_malloc both allocate through malloc; aligned_alloc and
//     posix_memalign, which neither uses, are not counted).
//   - AddressSanitizer builds, where the sanitizer owns malloc: its allocation hook
//     (__sanitizer_install_malloc_and_free_hooks) sees every allocation instead.
#include <atomic>
#include <cstddef>

#if !defined(__SANITIZE_ADDRESS__) && !defined(__GLIBC__)
#error "allocation_counter.hpp needs glibc or AddressSanitizer"
#endif

namespace pound::test {

inline std::atomic<long> g_allocations{0};
inline std::atomic<bool> g_counting{false};

inline void count_allocation() {
  if (g_counting.load(std::memory_order_relaxed)) g_allocations.fetch_add(1);
}

/// Allocations made during the object's life: count().
class CountAllocations {
 public:
  CountAllocations() : start_(g_allocations.load()) { g_counting = true; }
  ~CountAllocations() { g_counting = false; }
  long count() const { return g_allocations.load() - start_; }

 private:
  long start_;
};

}  // namespace pound::test

#if defined(__SANITIZE_ADDRESS__)
extern "C" int __sanitizer_install_malloc_and_free_hooks(void (*malloc_hook)(const volatile void*,
                                                                             std::size_t),
                                                         void (*free_hook)(const volatile void*));

namespace pound::test {
inline void sanitizer_malloc_hook(const volatile void*, std::size_t) {
  count_allocation();
}
inline void sanitizer_free_hook(const volatile void*) {}
inline const int g_hooks_installed =
    __sanitizer_install_malloc_and_free_hooks(sanitizer_malloc_hook, sanitizer_free_hook);
}  // namespace pound::test
#else
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
