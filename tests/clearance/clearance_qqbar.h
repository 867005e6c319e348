/* The clearance oracle's only contact with Calcium: real roots of a rational polynomial as exact algebraic
   numbers, and the exact sign of another rational polynomial at one of them. A C shim because Calcium
   0.4.1's headers (static inline functions that convert void* implicitly) are valid C but not C++. */
#ifndef BOXCYL_TESTS_CLEARANCE_QQBAR_H
#define BOXCYL_TESTS_CLEARANCE_QQBAR_H

#include <gmp.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct boxcyl_real_roots boxcyl_real_roots;

/* The distinct real roots of c[0] + c[1]x + ... + c[len-1]x^(len-1), a non-zero polynomial of degree >= 1. */
boxcyl_real_roots* boxcyl_real_roots_new(const mpq_srcptr* c, long len);
long boxcyl_real_roots_count(const boxcyl_real_roots* roots);
/* sign(g(x_i)), g given like c: exactly -1, 0 or +1. */
int boxcyl_real_roots_sign_at(const boxcyl_real_roots* roots, long i, const mpq_srcptr* g, long len);
void boxcyl_real_roots_free(boxcyl_real_roots* roots);

#ifdef __cplusplus
}
#endif

#endif
