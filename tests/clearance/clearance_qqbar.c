/* See clearance_qqbar.h. */
#include "clearance_qqbar.h"

#include <stdlib.h>

#include <calcium/qqbar.h> /* exact real algebraic numbers (Debian libcalcium-dev) */
#include <arb_poly.h>      /* certified ball evaluation (libflint-arb-dev) */
#include <flint/fmpq_poly.h>
#include <flint/fmpz_poly.h>

struct boxcyl_real_roots {
    long n;                /* distinct real roots */
    slong cap;             /* x's allocated length */
    qqbar_struct* x;       /* the roots, each with its minimal polynomial over Q */
    fmpq_poly_struct* mp;  /* the minimal polynomials as rational polynomials */
};

static void set_poly(fmpq_poly_t p, const mpq_srcptr* c, long len) {
    long i;
    fmpq_poly_zero(p);
    for (i = 0; i < len; ++i) fmpq_poly_set_coeff_mpq(p, i, c[i]);
}

boxcyl_real_roots* boxcyl_real_roots_new(const mpq_srcptr* c, long len) {
    boxcyl_real_roots* r = (boxcyl_real_roots*)malloc(sizeof *r);
    fmpq_poly_t p;
    fmpz_poly_t z;
    slong deg, i;
    qqbar_ptr all;
    fmpq_poly_init(p);
    fmpz_poly_init(z);
    set_poly(p, c, len);
    fmpq_poly_get_numerator(z, p);
    deg = fmpz_poly_degree(z);
    r->n = 0;
    r->cap = 0;
    r->x = NULL;
    r->mp = NULL;
    if (deg >= 1) {
        all = _qqbar_vec_init(deg);
        qqbar_roots_fmpz_poly(all, z, 0); /* sorted, with multiplicity */
        r->x = _qqbar_vec_init(deg);
        r->cap = deg;
        for (i = 0; i < deg; ++i) {
            if (!qqbar_is_real(all + i)) continue;
            if (r->n > 0 && qqbar_equal(all + i, r->x + r->n - 1)) continue;
            qqbar_set(r->x + r->n, all + i);
            r->n++;
        }
        _qqbar_vec_clear(all, deg);
        r->mp = (fmpq_poly_struct*)malloc((size_t)(r->n > 0 ? r->n : 1) * sizeof(fmpq_poly_struct));
        for (i = 0; i < r->n; ++i) {
            fmpq_poly_init(r->mp + i);
            fmpq_poly_set_fmpz_poly(r->mp + i, QQBAR_POLY(r->x + i));
        }
    }
    fmpz_poly_clear(z);
    fmpq_poly_clear(p);
    return r;
}

long boxcyl_real_roots_count(const boxcyl_real_roots* roots) { return roots->n; }

/* g(x) = 0 exactly when the (irreducible) minimal polynomial of x divides g; otherwise the remainder is
   non-zero at x and ball evaluation at rising precision finds its sign in finitely many steps. */
int boxcyl_real_roots_sign_at(const boxcyl_real_roots* roots, long i, const mpq_srcptr* g, long len) {
    fmpq_poly_t gp, rem;
    arb_t xe, val;
    arb_poly_t ap;
    slong prec;
    int s = 0;
    fmpq_poly_init(gp);
    fmpq_poly_init(rem);
    set_poly(gp, g, len);
    fmpq_poly_rem(rem, gp, roots->mp + i);
    if (!fmpq_poly_is_zero(rem)) {
        arb_init(xe);
        arb_init(val);
        arb_poly_init(ap);
        for (prec = 64; s == 0; prec *= 2) {
            qqbar_get_arb(xe, roots->x + i, prec);
            arb_poly_set_fmpq_poly(ap, rem, prec);
            arb_poly_evaluate(val, ap, xe, prec);
            if (arb_is_positive(val)) s = 1;
            else if (arb_is_negative(val)) s = -1;
        }
        arb_poly_clear(ap);
        arb_clear(val);
        arb_clear(xe);
    }
    fmpq_poly_clear(rem);
    fmpq_poly_clear(gp);
    return s;
}

void boxcyl_real_roots_free(boxcyl_real_roots* roots) {
    long i;
    if (roots->mp) {
        for (i = 0; i < roots->n; ++i) fmpq_poly_clear(roots->mp + i);
        free(roots->mp);
    }
    if (roots->x) _qqbar_vec_clear(roots->x, roots->cap);
    free(roots);
}
