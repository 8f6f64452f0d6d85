// Large allocations on transparent huge pages.
//
// The engine's particle fields and nodal arrays are vectors of 8 to 48 bytes
// per particle or node: at 10^6 particles, some 30 allocations of 8-48 MB.
// Each 4 KiB page of a fresh allocation costs a page fault at its first
// touch; on the project's virtual machine a fault costs about 20 us, so that
// set-up (particles generated and sorted) took 1.0-1.5 s per million
// particles, and every re-sort of a run, which permutes each field into a
// fresh vector, as long again. Asking the kernel for 2 MiB pages
// (madvise(MADV_HUGEPAGE), the Linux kernel's admin guide,
// "Transparent Hugepage Support") cuts the faults by 512 (docs/performance.md).
//
// The program's global operator new takes memory from malloc as the
// default does, and advises the whole pages of an allocation of 4 MiB or
// more. The advice is a hint: where transparent huge pages are off
// ("never") it does nothing, and nothing else changes. Linked into the
// executables only (an object library), never into the layers.
#include <sys/mman.h>

#include <cstdint>
#include <cstdlib>
#include <new>

namespace {

constexpr std::size_t small_page = 4096;
constexpr std::size_t advise_from = std::size_t{4} << 20;  // two huge pages

void* allocate(std::size_t bytes) {
  const std::size_t asked = bytes == 0 ? 1 : bytes;
  void* p = std::malloc(asked);
  while (p == nullptr) {  // as the default operator new ([new.delete.single])
    const std::new_handler handler = std::get_new_handler();
    if (handler == nullptr) throw std::bad_alloc();
    handler();
    p = std::malloc(asked);
  }
  if (bytes >= advise_from) {
    // The whole small pages inside [p, p + bytes): the kernel uses huge
    // pages for the aligned 2 MiB ranges among them.
    const std::uintptr_t lo = (reinterpret_cast<std::uintptr_t>(p) + small_page - 1) & ~(small_page - 1);
    const std::uintptr_t hi = (reinterpret_cast<std::uintptr_t>(p) + bytes) & ~(small_page - 1);
    if (hi > lo) madvise(reinterpret_cast<void*>(lo), hi - lo, MADV_HUGEPAGE);
  }
  return p;
}

}  // namespace

// Every form that pairs with free(): the plain, array and nothrow forms
// (std::stable_sort's buffer is nothrow new), so that no delete of ours
// frees what another allocator's new made; AddressSanitizer checks the
// pairing. The aligned forms are left to the library, whose new and
// delete pair with each other.
void* operator new(std::size_t bytes) { return allocate(bytes); }
void* operator new[](std::size_t bytes) { return allocate(bytes); }
void* operator new(std::size_t bytes, const std::nothrow_t&) noexcept {
  try {
    return allocate(bytes);
  } catch (const std::bad_alloc&) {
    return nullptr;
  }
}
void* operator new[](std::size_t bytes, const std::nothrow_t& tag) noexcept { return operator new(bytes, tag); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
void operator delete(void* p, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { std::free(p); }
