/* A malloc counter for tests/runs/no_step_allocations.sh: preloaded
 * (LD_PRELOAD) into a run, it counts the calls of malloc and realloc and
 * writes their number to the file MALLOC_COUNT_FILE names when the process
 * ends. Single-threaded programs only (hsri2d is). */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <stdio.h>
#include <stdlib.h>

static unsigned long n_calls;
static void *(*next_malloc)(size_t);
static void *(*next_realloc)(void *, size_t);

void *malloc(size_t n) {
  if (!next_malloc) next_malloc = (void *(*)(size_t))dlsym(RTLD_NEXT, "malloc");
  n_calls++;
  return next_malloc(n);
}

void *realloc(void *p, size_t n) {
  if (!next_realloc) next_realloc = (void *(*)(void *, size_t))dlsym(RTLD_NEXT, "realloc");
  n_calls++;
  return next_realloc(p, n);
}

__attribute__((destructor)) static void report(void) {
  const char *path = getenv("MALLOC_COUNT_FILE");
  FILE *f;
  if (!path) return;
  f = fopen(path, "w");
  if (!f) return;
  fprintf(f, "%lu\n", n_calls);
  fclose(f);
}
