/* The clearance oracle's only contact with FLINT and Arb: the real roots in [-1, 1] of a rational polynomial,
   isolated (or grouped) in intervals, and the exact sign of another rational polynomial at them. A C shim
   because these C headers are not all valid C++ (Arb's are kept out of C++). */
#ifndef BOXCYL_TESTS_CLEARANCE_ROOTS_H
#define BOXCYL_TESTS_CLEARANCE_ROOTS_H

#include <gmp.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct boxcyl_real_roots boxcyl_real_roots;

/* The real roots in [-1, 1] of c[0] + c[1]x + ... + c[len-1]x^(len-1), a non-zero polynomial, as groups: each
   group is the set of roots of one irreducible factor inside one interval (a rational root alone). Every real
   root in [-1, 1] lies in exactly one group; a group may hold none, one or several roots. */
boxcyl_real_roots* boxcyl_real_roots_new(const mpq_srcptr* c, long len);
/* The number of groups so far (refinement may add more). */
long boxcyl_real_roots_count(const boxcyl_real_roots* roots);
#define BOXCYL_UNDECIDED 2
/* sign(g(x)), exactly -1, 0 or +1, the same for every root x in group i; or BOXCYL_UNDECIDED when the group is
   still too coarse to tell (refine it and ask again). g given like c. */
int boxcyl_real_roots_sign_at(const boxcyl_real_roots* roots, long i, const mpq_srcptr* g, long len);
/* Whether group i holds a root, exactly: 1 yes, 0 no, -1 not known yet (refine it and ask again). */
int boxcyl_real_roots_nonempty(const boxcyl_real_roots* roots, long i);
/* Whether refinement found group i to hold no root (it is then skipped). */
int boxcyl_real_roots_empty(const boxcyl_real_roots* roots, long i);
/* Narrows group i (possibly splitting it: the other parts are appended as new groups, or emptying it). */
void boxcyl_real_roots_refine(boxcyl_real_roots* roots, long i);
void boxcyl_real_roots_free(boxcyl_real_roots* roots);

#ifdef __cplusplus
}
#endif

#endif
