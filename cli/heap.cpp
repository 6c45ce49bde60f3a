// The `umbra` program's heap. A render allocates its tables afresh (89k
// surfaces' polygons, edges and index: about 100 MB for refined_elephant),
// and with 4 KiB pages each first touch is a page fault: 24k of them, a
// fifth of a whole `umbra render` on this kind of VM. Linked with
// mimalloc (cmake/umbra_dependencies.cmake), the program asks for its heap
// in transparent huge pages: 6k faults. The libraries keep the system's
// malloc; only this program chooses. Nothing calls this file: it sets the
// option before the allocator starts. Builds without mimalloc (sanitizers,
// fuzzing) compile it empty.
#if defined(UMBRA_MIMALLOC)
#include <mimalloc.h>

#include <string_view>
#endif

namespace umbra::cli {

#if defined(UMBRA_MIMALLOC)
namespace {

/// "Large OS pages": mimalloc maps its segments 2 MiB aligned and advises
/// them as huge pages (MADV_HUGEPAGE: honoured under the kernel's THP mode
/// `madvise` as well as `always`); where the kernel refuses, 4 KiB pages as
/// before. mimalloc settles its page size when it starts, before any
/// library's initialiser, let alone main: set from main, the option left
/// 15k of the 24k faults. So it is set here, from the program's
/// .preinit_array, which runs once everything is loaded and relocated and
/// before any initialiser; mi_option_set only stores the value. A user's
/// own MIMALLOC_LARGE_OS_PAGES wins. It is looked up in `env`, the array
/// the loader hands over: libc's getenv has no environment yet this early
/// (its own initialiser sets it), and found nothing.
void enable_large_os_pages(int, char**, char** env) {
  constexpr std::string_view kName = "MIMALLOC_LARGE_OS_PAGES=";
  for (char** e = env; e != nullptr && *e != nullptr; ++e)
    if (std::string_view(*e).starts_with(kName)) return;
  mi_option_enable(mi_option_large_os_pages);
}

__attribute__((section(".preinit_array"),
               used)) void (*const preinit)(int, char**, char**) = enable_large_os_pages;

}  // namespace
#endif

}  // namespace umbra::cli
