/* Edge coverage for AFL++ from gcc's -fsanitize-coverage=trace-pc (used for the Fortran code of
 * the fuzz target, see scripts/fuzz.sh).
 *
 * Why: Debian's afl++ 4.04c GCC plugin (afl-gcc-fast) refuses to load in this gcc
 * ("GCC and plugin have incompatible versions": built against 12.2.0-14, the compiler is
 * 12.2.0-14+deb12u1), and there is no LLVM Fortran front end here. gcc/gfortran can still call
 * __sanitizer_cov_trace_pc() at the start of every basic block; this file turns those calls into
 * classic AFL edge hits (prev_block XOR cur_block) in AFL++'s shared-memory map. The forkserver,
 * the shared-memory setup and __afl_area_ptr come from AFL++'s own runtime
 * (/usr/lib/afl/afl-compiler-rt.o), linked next to this file. */
#include <stdint.h>

extern uint8_t *__afl_area_ptr;
extern uint32_t __afl_map_size;

#define FUZZ_MAP_SIZE 65536u /* AFL++'s default MAP_SIZE; the target never asks for more */

static __thread uintptr_t prev_loc;

void __sanitizer_cov_trace_pc(void) {
  uintptr_t pc = (uintptr_t)__builtin_return_address(0);
  /* mix the address so that nearby blocks land far apart in the map */
  uintptr_t cur = (pc ^ (pc >> 7) ^ (pc >> 17)) * 0x9E3779B1u;
  cur = (cur >> 11) & (FUZZ_MAP_SIZE - 1);
  uint8_t *hit = &__afl_area_ptr[cur ^ prev_loc];
  uint8_t v = (uint8_t)(*hit + 1);
  *hit = v ? v : 1; /* NeverZero: a counter wrapping to 0 would hide the edge */
  prev_loc = cur >> 1;
}
