/* See clearance_roots.h. */
#include "clearance_roots.h"

#include <stdlib.h>

#include <arb_calc.h> /* real root isolation and refinement by certified bisection (libflint-arb-dev) */
#include <arb_fmpz_poly.h>
#include <arb_poly.h> /* ball arithmetic on polynomials */
#include <flint/fmpq_poly.h>
#include <flint/fmpz_poly.h>
#include <flint/fmpz_poly_factor.h>

/* A group: the roots of the irreducible factor f in the open interval (a, b), all of them treated alike.
   isolated: exactly one root in (a, b) (sign change at the ends, derivative non-zero between: arb_calc's
   certificate), else at least zero. exact: f is linear and a = b is its (rational) root. */
/* A group that is neither isolated nor shows a sign change gets its root count from a Sturm sequence only once
   its isolation rounds reach this depth: until then refining is cheaper (it mostly empties such groups), and
   FLINT's Sturm sequence costs milliseconds on the edge equations' large coefficients. */
#define STURM_DEPTH 400
typedef struct {
    slong factor;
    arf_interval_struct iv;
    int isolated;
    int exact;
    int empty;   /* refined away: no root left */
    slong prec;  /* working precision of the ball evaluations on this group */
    slong depth; /* bisection depth of the next isolation round */
} group;

struct boxcyl_real_roots {
    slong nfac;
    fmpz_poly_struct* f;  /* the distinct irreducible factors (primitive, degree >= 1) */
    fmpq_poly_struct* fq; /* the same as rational polynomials (for remainders) */
    slong n, cap;
    group* g;
};

static void set_poly(fmpq_poly_t p, const mpq_srcptr* c, long len) {
    long i;
    fmpq_poly_zero(p);
    for (i = 0; i < len; ++i) fmpq_poly_set_coeff_mpq(p, i, c[i]);
}

/* Encloses p and p' (order 1 or 2) on the ball x by the Taylor form at its midpoint m: with
   p(m + y) = sum g_i y^i, |y| <= r, p = g_0 + [sum_{i>=1} |g_i| r^i] and p' = g_1 + [sum_{i>=2} i |g_i| r^(i-1)].
   Rigorous (ball arithmetic throughout), and far tighter than Horner's scheme on a ball when the
   coefficients are much larger than the values (the edge equations' cancellation). */
static void taylor_enclosure(arb_ptr out, const arb_poly_t p, const arb_t x, slong order, slong prec) {
    arb_poly_t g;
    arb_t m, r, acc, t;
    mag_t e;
    slong n = arb_poly_length(p), i, k;
    arb_poly_init(g);
    arb_init(m);
    arb_init(r);
    arb_init(acc);
    arb_init(t);
    mag_init(e);
    arb_set_arf(m, arb_midref(x));
    arf_set_mag(arb_midref(r), arb_radref(x));
    arb_poly_taylor_shift(g, p, m, prec);
    for (k = 0; k < order; ++k) {
        arb_zero(acc);
        for (i = n - 1; i > k; --i) { /* acc = sum_{i>k} C(i,k) |g_i| r^(i-k), by Horner in r */
            arb_abs(t, g->coeffs + i);
            if (k == 1) arb_mul_ui(t, t, (ulong)i, prec);
            arb_add(acc, acc, t, prec);
            arb_mul(acc, acc, r, prec);
        }
        if (k < n) arb_set(out + k, g->coeffs + k);
        else arb_zero(out + k);
        if (k == 1 && n <= 1) arb_zero(out + k);
        arb_get_mag(e, acc);
        arb_add_error_mag(out + k, e);
    }
    mag_clear(e);
    arb_clear(t);
    arb_clear(acc);
    arb_clear(r);
    arb_clear(m);
    arb_poly_clear(g);
}

/* f and f' on a ball, for arb_calc. */
static int factor_func(arb_ptr out, const arb_t x, void* param, slong order, slong prec) {
    arb_poly_t p;
    arb_poly_init(p);
    arb_poly_set_fmpz_poly(p, (const fmpz_poly_struct*)param, prec);
    taylor_enclosure(out, p, x, order < 2 ? order : 2, prec);
    arb_poly_clear(p);
    return 0;
}

static group* push_group(boxcyl_real_roots* r, slong factor, const arf_interval_t iv, int isolated, slong prec,
                         slong depth) {
    group* q;
    if (r->n == r->cap) {
        r->cap = r->cap ? 2 * r->cap : 8;
        r->g = (group*)realloc(r->g, (size_t)r->cap * sizeof(group));
    }
    q = r->g + r->n++;
    q->factor = factor;
    arf_interval_init(&q->iv);
    arf_interval_set(&q->iv, iv);
    q->isolated = isolated;
    q->exact = 0;
    q->empty = 0;
    q->prec = prec;
    q->depth = depth;
    return q;
}

/* -log2 of the width of [a, b] (a lower bound; 0 if the width is at least 1). */
static slong width_bits(const arf_interval_t iv) {
    arf_t w;
    slong k;
    arf_init(w);
    arf_sub(w, &iv->b, &iv->a, 30, ARF_RND_UP);
    k = arf_is_zero(w) ? 0 : -arf_abs_bound_lt_2exp_si(w);
    arf_clear(w);
    return k > 0 ? k : 0;
}

/* Isolates the roots of factor k in iv (arb_calc's certified bisection): each isolated block becomes a group,
   and each run of adjacent blocks that arb_calc could neither exclude nor isolate becomes one group (a cluster
   of roots, or a region where the precision did not suffice). The first group replaces group `slot` when
   slot >= 0 (emptied if there is none). */
/* The groups arb_calc's blocks form (isolated blocks alone, runs of adjacent undecided blocks merged). */
static slong form_groups(arf_interval_ptr out, int* iso, const arf_interval_struct* blocks, const int* flags, slong nb) {
    slong j, n = 0;
    for (j = 0; j < nb; ++j) {
        iso[n] = flags[j] == 1;
        arf_interval_set(out + n, blocks + j);
        if (!iso[n])
            while (j + 1 < nb && flags[j + 1] != 1 && arf_equal(&blocks[j + 1].a, &out[n].b)) arf_set(&out[n].b, &blocks[++j].b);
        ++n;
    }
    return n;
}

static void isolate(boxcyl_real_roots* r, slong k, const arf_interval_t iv, slong depth, slong prec, slong slot) {
    arf_interval_ptr blocks, grp;
    int *flags, *iso;
    slong nb, ng, j;
    const slong deg = fmpz_poly_degree(r->f + k);
    const slong top = 4 * (fmpz_poly_max_bits(r->f + k) < 0 ? -fmpz_poly_max_bits(r->f + k) : fmpz_poly_max_bits(r->f + k)) +
                      8 * depth + 256;
    for (;;) {
        nb = arb_calc_isolate_roots(&blocks, &flags, factor_func, r->f + k, iv, depth, 64 * depth + 256, deg, prec);
        grp = _arf_interval_vec_init(nb > 0 ? nb : 1);
        iso = (int*)flint_malloc((size_t)(nb > 0 ? nb : 1) * sizeof(int));
        ng = form_groups(grp, iso, blocks, flags, nb);
        _arf_interval_vec_clear(blocks, nb);
        flint_free(flags);
        /* more groups than roots can exist: some are mere imprecision; retry at twice the precision (a bound
           keeps this finite; the groups are valid whatever the precision) */
        if (ng <= deg || prec >= top) break;
        _arf_interval_vec_clear(grp, nb > 0 ? nb : 1);
        flint_free(iso);
        prec *= 2;
    }
    for (j = 0; j < ng; ++j) {
        if (j == 0 && slot >= 0) {
            group* q = r->g + slot;
            arf_interval_set(&q->iv, grp + j);
            q->isolated = iso[j];
            q->prec = prec;
            q->depth = 2 * depth;
        } else {
            push_group(r, k, grp + j, iso[j], prec, 2 * depth);
        }
    }
    if (ng == 0 && slot >= 0) r->g[slot].empty = 1;
    _arf_interval_vec_clear(grp, nb > 0 ? nb : 1);
    flint_free(iso);
}

boxcyl_real_roots* boxcyl_real_roots_new(const mpq_srcptr* c, long len) {
    boxcyl_real_roots* r = (boxcyl_real_roots*)calloc(1, sizeof *r);
    fmpq_poly_t p;
    fmpz_poly_t z;
    fmpz_poly_factor_t fac;
    arf_interval_t unit;
    slong i;
    fmpq_poly_init(p);
    fmpz_poly_init(z);
    fmpz_poly_factor_init(fac);
    arf_interval_init(unit);
    set_poly(p, c, len);
    fmpq_poly_get_numerator(z, p);
    if (fmpz_poly_degree(z) >= 1) {
        fmpz_poly_factor(fac, z); /* distinct irreducible factors; multiplicities are irrelevant here */
        r->nfac = fac->num;
        r->f = (fmpz_poly_struct*)malloc((size_t)(fac->num > 0 ? fac->num : 1) * sizeof(fmpz_poly_struct));
        r->fq = (fmpq_poly_struct*)malloc((size_t)(fac->num > 0 ? fac->num : 1) * sizeof(fmpq_poly_struct));
        arf_set_si(&unit->a, -1);
        arf_set_si(&unit->b, 1);
        for (i = 0; i < fac->num; ++i) {
            fmpz_poly_init(r->f + i);
            fmpz_poly_set(r->f + i, fac->p + i);
            fmpq_poly_init(r->fq + i);
            fmpq_poly_set_fmpz_poly(r->fq + i, r->f + i);
            if (fmpz_poly_degree(r->f + i) == 1) {
                /* the rational root -f0/f1: kept (as an exact group) when it lies in [-1, 1] */
                fmpq_t x;
                fmpq_init(x);
                fmpq_set_fmpz_frac(x, r->f[i].coeffs, r->f[i].coeffs + 1);
                fmpq_neg(x, x);
                if (fmpz_cmpabs(fmpq_numref(x), fmpq_denref(x)) <= 0) {
                    group* q = push_group(r, i, unit, 1, 64, 0);
                    q->exact = 1;
                }
                fmpq_clear(x);
            } else {
                /* irreducible of degree >= 2: no rational root, so none at -1 or 1 */
                isolate(r, i, unit, 48, 128, -1);
            }
        }
    }
    arf_interval_clear(unit);
    fmpz_poly_factor_clear(fac);
    fmpz_poly_clear(z);
    fmpq_poly_clear(p);
    return r;
}

long boxcyl_real_roots_count(const boxcyl_real_roots* roots) { return roots->n; }

int boxcyl_real_roots_empty(const boxcyl_real_roots* roots, long i) { return roots->g[i].empty; }

/* sign(g(x)) for the roots x of group i. g(x) = 0 exactly when the irreducible factor divides g (then at every
   root of the group); otherwise g(x) != 0 at every root of that factor and the remainder's sign on the
   group's interval, by the Taylor form in ball arithmetic, is either certain or not yet. */
int boxcyl_real_roots_sign_at(const boxcyl_real_roots* roots, long i, const mpq_srcptr* g, long len) {
    const group* q = roots->g + i;
    fmpq_poly_t gp, rem;
    int s = BOXCYL_UNDECIDED;
    fmpq_poly_init(gp);
    fmpq_poly_init(rem);
    set_poly(gp, g, len);
    fmpq_poly_rem(rem, gp, roots->fq + q->factor);
    if (fmpq_poly_is_zero(rem)) {
        s = 0;
    } else if (fmpq_poly_degree(rem) == 0) {
        s = fmpz_sgn(fmpq_poly_numref(rem)); /* a constant remainder: g(x) itself */
    } else {
        arb_poly_t ap;
        arb_t x, val;
        arb_poly_init(ap);
        arb_init(x);
        arb_init(val);
        arb_poly_set_fmpq_poly(ap, rem, q->prec);
        arf_interval_get_arb(x, &q->iv, q->prec);
        taylor_enclosure(val, ap, x, 1, q->prec);
        if (arb_is_positive(val)) s = 1;
        else if (arb_is_negative(val)) s = -1;
        arb_clear(val);
        arb_clear(x);
        arb_poly_clear(ap);
    }
    fmpq_poly_clear(rem);
    fmpq_poly_clear(gp);
    return s;
}

/* The number of roots of the squarefree f in the open interval (a, b) (dyadic ends, f(a), f(b) != 0): with
   a = A 2^e, b = B 2^e, h(z) = f(2^e (A + (B - A) z)) scaled to integers has them in (0, 1), and
   w(y) = (1 + y)^n h(1 / (1 + y)) at y > 0; FLINT's Sturm sequence counts w's positive roots. */
static slong count_in(const fmpz_poly_t f, const arf_interval_t iv) {
    fmpz_t ma, ea, mb, eb, one;
    fmpz_poly_t lin, s, h;
    slong n = fmpz_poly_degree(f), i, e, nneg, npos;
    fmpz_init(ma);
    fmpz_init(ea);
    fmpz_init(mb);
    fmpz_init(eb);
    fmpz_init(one);
    fmpz_poly_init(lin);
    fmpz_poly_init(s);
    fmpz_poly_init(h);
    arf_get_fmpz_2exp(ma, ea, &iv->a);
    arf_get_fmpz_2exp(mb, eb, &iv->b);
    e = fmpz_cmp(ea, eb) < 0 ? fmpz_get_si(ea) : fmpz_get_si(eb);
    fmpz_mul_2exp(ma, ma, (ulong)(fmpz_get_si(ea) - e));
    fmpz_mul_2exp(mb, mb, (ulong)(fmpz_get_si(eb) - e));
    fmpz_poly_set_coeff_fmpz(lin, 0, ma);
    fmpz_sub(mb, mb, ma);
    fmpz_poly_set_coeff_fmpz(lin, 1, mb); /* A + (B - A) z */
    /* s(x) = 2^(max(-e,0) n) f(2^e x) as an integer polynomial */
    fmpz_poly_set(s, f);
    for (i = 0; i <= n; ++i) {
        if (e >= 0) fmpz_mul_2exp(s->coeffs + i, s->coeffs + i, (ulong)(e * i));
        else fmpz_mul_2exp(s->coeffs + i, s->coeffs + i, (ulong)(-e * (n - i)));
    }
    fmpz_poly_compose(h, s, lin);
    fmpz_poly_reverse(h, h, n + 1);
    fmpz_one(one);
    fmpz_poly_taylor_shift(h, h, one);
    _fmpz_poly_num_real_roots_sturm(&nneg, &npos, h->coeffs, h->length);
    fmpz_poly_clear(h);
    fmpz_poly_clear(s);
    fmpz_poly_clear(lin);
    fmpz_clear(one);
    fmpz_clear(eb);
    fmpz_clear(mb);
    fmpz_clear(ea);
    fmpz_clear(ma);
    return npos;
}

/* sign(f(x)) at a dyadic point, exactly (f(x) != 0 there: f has no rational root or is linear with x not it). */
static int sign_at_point(const fmpz_poly_t f, const arf_t x) {
    arb_t v, y;
    slong prec;
    int s = 0;
    arb_init(v);
    arb_init(y);
    arb_set_arf(y, x);
    for (prec = 64; s == 0; prec *= 2) {
        arb_fmpz_poly_evaluate_arb(v, f, y, prec);
        s = arb_is_positive(v) ? 1 : (arb_is_negative(v) ? -1 : 0);
    }
    arb_clear(y);
    arb_clear(v);
    return s;
}

/* 1: group i holds a root; 0: it holds none; -1: not known at this resolution (refine it). */
int boxcyl_real_roots_nonempty(const boxcyl_real_roots* roots, long i) {
    const group* q = roots->g + i;
    const fmpz_poly_struct* f = roots->f + q->factor;
    if (q->empty) return 0;
    if (q->exact || q->isolated) return 1;
    if (sign_at_point(f, &q->iv.a) != sign_at_point(f, &q->iv.b)) return 1; /* a sign change: an odd count */
    if (q->depth < STURM_DEPTH) return -1;
    return count_in(f, &q->iv) > 0;
}

/* An isolated group: its interval narrowed to about twice as many bits (arb_calc's bisection keeps the sign
   change); any other: isolation again inside its interval, deeper. The precision rises too, so repeated
   refinement decides every sign that is not exactly zero. */
void boxcyl_real_roots_refine(boxcyl_real_roots* roots, long i) {
    group* q = roots->g + i;
    const slong k = width_bits(&q->iv);
    if (q->empty || q->exact) return;
    if (q->isolated) {
        const slong iter = k > 64 ? k : 64;
        const slong prec = 2 * (k + iter) + 128 > 2 * q->prec ? 2 * (k + iter) + 128 : 2 * q->prec;
        arf_interval_t out;
        arf_interval_init(out);
        if (arb_calc_refine_root_bisect(out, factor_func, roots->f + q->factor, &q->iv, iter, prec) !=
            ARB_CALC_IMPRECISE_INPUT)
            arf_interval_swap(&q->iv, out); /* on success or an early stop: still one root with a sign change */
        q->prec = prec;
        arf_interval_clear(out);
    } else {
        arf_interval_t iv;
        const slong depth = q->depth;
        const slong prec = 2 * (k + depth) + 128 > 2 * q->prec ? 2 * (k + depth) + 128 : 2 * q->prec;
        arf_interval_init(iv);
        arf_interval_set(iv, &q->iv);
        isolate(roots, q->factor, iv, depth, prec, i);
        arf_interval_clear(iv);
    }
}

void boxcyl_real_roots_free(boxcyl_real_roots* roots) {
    slong i;
    for (i = 0; i < roots->n; ++i) arf_interval_clear(&roots->g[i].iv);
    free(roots->g);
    for (i = 0; i < roots->nfac; ++i) {
        fmpz_poly_clear(roots->f + i);
        fmpq_poly_clear(roots->fq + i);
    }
    free(roots->f);
    free(roots->fq);
    free(roots);
}
