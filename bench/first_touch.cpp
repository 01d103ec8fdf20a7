// first_touch: what this machine's kernel charges for memory a process
// writes for the first time, the floor under sfrender's system time on big
// scenes (bench/scale_bench.sh prints it beside them).
//
//   first_touch [--gib N] [--passes P] [--small-pages]
//
// Each pass maps N GiB, advises 2 MiB pages (as sfrender does for its big
// arrays) unless --small-pages, writes a byte in every 4 KiB page, and
// unmaps it; it prints the pass's wall and system time. The first pass
// takes memory the process never had; the later ones, within seconds, are
// usually given the pages the pass before gave back.
#include <sys/mman.h>
#include <sys/resource.h>

#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdio>
#include <cstdlib>

namespace {

double systemSeconds() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_stime.tv_sec) +
         static_cast<double>(usage.ru_stime.tv_usec) * 1e-6;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Times a process's first writes to fresh memory"};
  double gib = 2.0;
  int passes = 4;
  bool smallPages = false;
  app.add_option("--gib", gib, "GiB mapped each pass")->check(CLI::Range(0.01, 64.0));
  app.add_option("--passes", passes, "passes")->check(CLI::Range(1, 100));
  app.add_flag("--small-pages", smallPages, "no advice of 2 MiB pages");
  CLI11_PARSE(app, argc, argv);

  const std::size_t bytes = static_cast<std::size_t>(gib * (1 << 30)) & ~std::size_t{4095};
  std::printf("pass  wall s  system s  GB/s (wall)\n");
  for (int pass = 1; pass <= passes; ++pass) {
    const auto start = std::chrono::steady_clock::now();
    const double systemBefore = systemSeconds();
    void* room = ::mmap(nullptr, bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (room == MAP_FAILED) {
      std::fprintf(stderr, "first_touch: cannot map %.2f GiB\n", gib);
      return 1;
    }
#if defined(MADV_HUGEPAGE)
    if (!smallPages) ::madvise(room, bytes, MADV_HUGEPAGE);
#endif
    volatile char* page = static_cast<char*>(room);
    for (std::size_t at = 0; at < bytes; at += 4096) page[at] = 1;
    ::munmap(room, bytes);
    const double wall =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("%4d  %6.3f  %8.3f  %5.2f\n", pass, wall, systemSeconds() - systemBefore,
                static_cast<double>(bytes) / wall * 1e-9);
  }
  return 0;
}
