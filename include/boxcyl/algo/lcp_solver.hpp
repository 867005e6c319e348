// A linear complementarity problem (LCP) solver for the LCP method: Lemke's complementary pivoting method.
//
// The LCP(q, M): find z ∈ ℝᴺ with  z ≥ 0,  w = q + M z ≥ 0,  zᵀw = 0.
//
// Lemke's method adds an artificial variable z0 with covering vector e = (1, …, 1):
//     w − M z − e z0 = q,
// starts from the almost-complementary basis {w with one wᵣ replaced by z0} that makes all basic
// values ≥ 0, and then pivots: the variable entering is always the complement of the one that just
// left, until z0 leaves (a solution) or the entering column has no positive entry (ray termination).
// For copositive-plus M (every positive-semidefinite M, e.g. the KKT matrix of a convex QP, the LCP method
// eq. (8)) ray termination proves the LCP infeasible; a feasible LCP is always solved.
//
// Degeneracy: ties in the ratio test are broken by the lexicographic minimum-ratio rule on the rows of
// [ basic values | B⁻¹ ] (B⁻¹ is the w-block of the tableau, which starts as the identity). Every row
// of that matrix then stays lexicographically positive, so the method behaves as on a perturbed,
// nondegenerate problem q + (ε, ε², …): no almost-complementary basis repeats and the path is finite.
// With one exception for speed: when z0's row ties for the smallest plain ratio it leaves at once,
// which already yields a solution (every basic value stays ≥ 0, z0 becomes 0).
//
// Arithmetic: any ordered field T. For exact T (GMP rationals, quadratic-field numbers) the result is
// exact and the iteration cap is only a safety net that the theory says never triggers (there are at
// most N·2^(N−1) almost-complementary bases and a lexicographic path visits each at most once).
// For float/double the signs are taken as computed (threshold 0, no epsilons); rounding can then
// cause cycling or a spurious ray, reported as max_iterations / no_solution, never looped on.
//
// Fixed size N, storage in std::array: no allocation by the solver itself.
#pragma once

#include <array>    // tableau and results
#include <cstddef>  // std::size_t

#include "boxcyl/number/traits.hpp"

namespace boxcyl::algo {

enum class LcpStatus {
    solved,          // z, w solve the LCP
    no_solution,     // ray termination: for copositive-plus M the LCP is infeasible
    max_iterations,  // iteration cap reached (floating point only; never for exact T)
};

template <class T, std::size_t N>
struct LcpResult {
    LcpStatus status = LcpStatus::no_solution;
    std::array<T, N> z{};  // meaningful only when status == solved
    std::array<T, N> w{};  // w = q + M z (the tableau's values, exact for exact T)
    std::size_t pivots = 0;  // pivots performed, the initial z0 pivot included
};

template <class T, std::size_t N>
using LcpMatrix = std::array<std::array<T, N>, N>;

// The number of almost-complementary bases, N·2^(N−1), bounds the pivots of a lexicographic Lemke
// path; one more covers the initial pivot. Saturates instead of overflowing for large N.
constexpr std::size_t lcp_iteration_bound(std::size_t n) {
    if (n == 0) return 1;
    std::size_t bound = n;
    for (std::size_t i = 1; i < n; ++i) {
        if (bound > static_cast<std::size_t>(-1) / 2) return static_cast<std::size_t>(-1) - 1;
        bound *= 2;
    }
    return bound + 2;
}

namespace detail {

// Tableau of  w − M z − e z0 = q  in the current basis: columns 0..N−1 are w (so they hold B⁻¹),
// N..2N−1 are z, 2N is z0 and 2N+1 the basic values.
template <class T, std::size_t N>
class LemkeTableau {
public:
    static constexpr std::size_t kZ0 = 2 * N;
    static constexpr std::size_t kRhs = 2 * N + 1;
    static constexpr std::size_t kCols = 2 * N + 2;
    static constexpr std::size_t kNone = static_cast<std::size_t>(-1);

    LemkeTableau(const std::array<T, N>& q, const LcpMatrix<T, N>& M) {
        for (std::size_t i = 0; i < N; ++i) {
            for (std::size_t j = 0; j < N; ++j) {
                t_[i][j] = T(i == j ? 1 : 0);
                t_[i][N + j] = -M[i][j];
            }
            t_[i][kZ0] = T(-1);
            t_[i][kRhs] = q[i];
            basis_[i] = i;
        }
    }

    const T& at(std::size_t i, std::size_t c) const { return t_[i][c]; }
    std::size_t basic(std::size_t i) const { return basis_[i]; }

    // The initial pivot brings z0 in. z0 must rise to max(−qᵢ); the row leaving is the
    // lexicographically smallest (qᵢ, B⁻¹ row i) — with B = I that is the most negative qᵢ, ties
    // going to the larger index — which is exactly what keeps every row lexicographically positive
    // after the pivot.
    std::size_t initial_row() const {
        std::size_t best = 0;
        for (std::size_t i = 1; i < N; ++i)
            if (lex_less_plain(i, best)) best = i;
        return best;
    }

    // Ratio test for entering column s: among rows with a positive entry, the lexicographic minimum
    // of [value | B⁻¹ row] / entry; z0's row wins any tie in the plain ratio. kNone: ray.
    std::size_t leaving_row(std::size_t s) const {
        std::size_t best = kNone;
        std::size_t z0_row = kNone;
        for (std::size_t i = 0; i < N; ++i) {
            if (!(sign_of(t_[i][s]) > 0)) continue;
            if (basis_[i] == kZ0) z0_row = i;
            if (best == kNone || lex_ratio_compare(i, best, s) < 0) best = i;
        }
        if (z0_row != kNone && z0_row != best && ratio_compare(z0_row, best, s, kRhs) == 0) return z0_row;
        return best;
    }

    // Gauss–Jordan pivot on (r, s); the pivot column becomes the unit vector exactly.
    void pivot(std::size_t r, std::size_t s) {
        const T p = t_[r][s];
        for (std::size_t c = 0; c < kCols; ++c)
            if (c != s && sign_of(t_[r][c]) != 0) t_[r][c] /= p;
        t_[r][s] = T(1);
        for (std::size_t i = 0; i < N; ++i) {
            if (i == r || sign_of(t_[i][s]) == 0) continue;
            const T f = t_[i][s];
            for (std::size_t c = 0; c < kCols; ++c)
                if (c != s && sign_of(t_[r][c]) != 0) t_[i][c] -= f * t_[r][c];
            t_[i][s] = T(0);
        }
        basis_[r] = s;
    }

private:
    // Sign of aᵢ꜀/aᵢₛ − aⱼ꜀/aⱼₛ for positive aᵢₛ, aⱼₛ, without dividing.
    int ratio_compare(std::size_t i, std::size_t j, std::size_t s, std::size_t c) const {
        return sign_of(T(t_[i][c] * t_[j][s] - t_[j][c] * t_[i][s]));
    }
    int lex_ratio_compare(std::size_t i, std::size_t j, std::size_t s) const {
        if (const int r = ratio_compare(i, j, s, kRhs); r != 0) return r;
        for (std::size_t c = 0; c < N; ++c)
            if (const int r = ratio_compare(i, j, s, c); r != 0) return r;
        return 0;  // unreachable: rows of B⁻¹ are linearly independent
    }
    bool lex_less_plain(std::size_t i, std::size_t j) const {
        if (const int r = sign_of(T(t_[i][kRhs] - t_[j][kRhs])); r != 0) return r < 0;
        for (std::size_t c = 0; c < N; ++c)
            if (const int r = sign_of(T(t_[i][c] - t_[j][c])); r != 0) return r < 0;
        return false;
    }

    std::array<std::array<T, kCols>, N> t_;
    std::array<std::size_t, N> basis_;
};

}  // namespace detail

// Solves LCP(q, M) by Lemke's method (see the file comment). `max_pivots` caps the pivots; the
// default is the theoretical bound for a lexicographic path, so for exact T it never triggers.
template <class T, std::size_t N>
LcpResult<T, N> solve_lcp(const std::array<T, N>& q, const LcpMatrix<T, N>& M,
                          std::size_t max_pivots = lcp_iteration_bound(N)) {
    static_assert(N > 0, "boxcyl::algo::solve_lcp: empty problem");
    using Tableau = detail::LemkeTableau<T, N>;
    LcpResult<T, N> result;

    // q ≥ 0: z = 0 is a solution (the trivial basis is complementary and feasible).
    bool trivial = true;
    for (std::size_t i = 0; i < N; ++i)
        if (sign_of(q[i]) < 0) trivial = false;
    if (trivial) {
        result.status = LcpStatus::solved;
        for (std::size_t i = 0; i < N; ++i) {
            result.z[i] = T(0);
            result.w[i] = q[i];
        }
        return result;
    }

    Tableau tab(q, M);
    std::size_t r = tab.initial_row();
    std::size_t entering = Tableau::kZ0;
    for (;;) {
        if (result.pivots == max_pivots) {
            result.status = LcpStatus::max_iterations;
            return result;
        }
        const std::size_t leaving = tab.basic(r);
        tab.pivot(r, entering);
        ++result.pivots;
        if (leaving == Tableau::kZ0) break;  // z0 = 0: complementary and feasible
        // The complement of the variable that left enters: wⱼ ↔ zⱼ.
        entering = leaving < N ? leaving + N : leaving - N;
        r = tab.leaving_row(entering);
        if (r == Tableau::kNone) {
            result.status = LcpStatus::no_solution;  // secondary ray
            return result;
        }
    }

    result.status = LcpStatus::solved;
    for (std::size_t i = 0; i < N; ++i) {
        result.z[i] = T(0);
        result.w[i] = T(0);
    }
    for (std::size_t i = 0; i < N; ++i) {
        const std::size_t v = tab.basic(i);
        if (v < N) result.w[v] = tab.at(i, Tableau::kRhs);
        else result.z[v - N] = tab.at(i, Tableau::kRhs);
    }
    return result;
}

}  // namespace boxcyl::algo
