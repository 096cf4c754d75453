// ctest: labels quick
/**
 * Unit test: SparseDirect's solve of saddle-point systems with the
 * multipliers eliminated (a regularized elimination preconditioning
 * iterative refinement) against UMFPACK's LU of the whole system. The
 * systems have the structure of tribos' contact systems: K a stiffness of
 * a chain of springs in 2D (symmetric; singular in one case, a body held
 * by its contact only), then per slave node a block of multiplier rows:
 * open (D = I, H = 0), closed frictionless (a gap row without multiplier
 * entries, tangential rows t . lambda), sticking (no multiplier entries at
 * all, G and H unrelated: unsymmetric). Asserts a relative difference
 * below 1e-10 and a residual below 1e-12 |b|, that the elimination was
 * used where the eliminated matrix is symmetric positive definite (with
 * CHOLMOD) and not where it is not (stick rows: LU of the whole system),
 * and
 * that a pattern the elimination does not apply to (multiplier rows
 * coupled across nodes) falls back to LU with the same solution.
 */

#include <tribos/solver/sparse_direct.h>

#include <deal.II/base/mpi.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <cmath>
#include <iostream>
#include <map>
#include <random>
#include <vector>

using namespace tribos;

namespace
{
  using Entries = std::map<std::pair<unsigned int, unsigned int>, double>;

  enum class Node
  {
    open,
    closed,
    stick
  };

  /** The system: n_u displacements (1D spring chain per component, 2
   * components), then 2 multipliers per slave node in @p nodes; the k-th
   * slave node sits at dofs 4k, 4k+1 and is paired with dofs 4k+2..4k+5.
   * @p anchored: the chain is tied to the ground at its first node. */
  Entries
  make_system(const unsigned int       n_u,
              const std::vector<Node> &nodes,
              const bool               anchored,
              const bool               cross_coupled,
              const bool               geometric,
              std::mt19937            &random)
  {
    std::uniform_real_distribution<double> uniform(0.5, 1.5);
    Entries                                a;
    for (unsigned int c = 0; c < 2; ++c)
      for (unsigned int i = c; i + 2 < n_u; i += 2)
      {
        const double k = 1e3 * uniform(random);
        a[{i, i}] += k;
        a[{i + 2, i + 2}] += k;
        a[{i, i + 2}] -= k;
        a[{i + 2, i}] -= k;
      }
    if (anchored)
      for (unsigned int c = 0; c < 2; ++c)
        a[{c, c}] += 1e3;
    for (unsigned int k = 0; k < nodes.size(); ++k)
    {
      const unsigned int row = n_u + 2 * k;
      // Weights of the slave node and its master segment, a normal n and
      // tangent t; the contact force on the dofs is G lambda.
      const double w[3]  = {1., -uniform(random) / 2, 0.};
      const double angle = 0.3 * uniform(random);
      const double n[2]  = {std::sin(angle), std::cos(angle)};
      const double t[2]  = {-n[1], n[0]};
      const double area  = 0.1 * uniform(random);
      const double c     = 1e3 * uniform(random);
      for (unsigned int j = 0; j < 3; ++j)
        for (unsigned int d = 0; d < 2; ++d)
        {
          const unsigned int dof = 4 * k + 2 * j + d;
          if (dof >= n_u)
            continue;
          // G: the force on dof from lambda_d' is area w_j delta(d, d').
          a[{dof, row + d}] += area * w[j];
          if (nodes[k] == Node::closed)
          {
            a[{row, dof}] += c * w[j] * n[d];
            if (geometric) // derivatives of the tangent: unsymmetric
              a[{row + 1, dof}] += 0.01 * uniform(random);
          }
          else if (nodes[k] == Node::stick)
            for (unsigned int r = 0; r < 2; ++r)
              a[{row + r, dof}] +=
                c * w[j] * uniform(random) * (r == 0 ? n[d] : t[d]);
        }
      if (nodes[k] == Node::open)
        for (unsigned int d = 0; d < 2; ++d)
          a[{row + d, row + d}] = area;
      else if (nodes[k] == Node::closed)
        for (unsigned int d = 0; d < 2; ++d)
          a[{row + 1, row + d}] = t[d];
      if (cross_coupled && k > 0)
        a[{row, row - 1}] = 0.1;
    }
    return a;
  }

  TrilinosWrappers::SparseMatrix
  to_matrix(const Entries &a, const unsigned int n)
  {
    DynamicSparsityPattern pattern(n, n);
    for (const auto &[ij, v] : a)
      pattern.add(ij.first, ij.second);
    TrilinosWrappers::SparseMatrix matrix;
    matrix.reinit(complete_index_set(n),
                  complete_index_set(n),
                  pattern,
                  MPI_COMM_WORLD);
    for (const auto &[ij, v] : a)
      matrix.set(ij.first, ij.second, v);
    matrix.compress(VectorOperation::insert);
    return matrix;
  }

  /** Solve one system both ways; false if a check fails. */
  bool
  check(const std::string       &name,
        const unsigned int       n_u,
        const std::vector<Node> &nodes,
        const bool               anchored,
        const bool               cross_coupled,
        const bool               geometric,
        const std::string       &expected_method,
        std::mt19937            &random)
  {
    const unsigned int n = n_u + 2 * nodes.size();
    const auto         a =
      make_system(n_u, nodes, anchored, cross_coupled, geometric, random);
    const auto           matrix = to_matrix(a, n);
    SparseDirect::Vector b(complete_index_set(n), MPI_COMM_WORLD), x(b),
      reference(b);
    std::uniform_real_distribution<double> uniform(-1, 1);
    for (unsigned int i = 0; i < n; ++i)
      b[i] = uniform(random);

    SparseDirect lu, eliminated;
    eliminated.set_multiplier_blocks(n_u, 2);
    bool ok =
      lu.solve(matrix, 1, reference, b) && eliminated.solve(matrix, 1, x, b);
    // A second solve with new values on the same pattern reuses the
    // analysis.
    auto changed = matrix.trilinos_matrix();
    changed.Scale(1.5);
    TrilinosWrappers::SparseMatrix scaled;
    scaled.reinit(changed);
    SparseDirect::Vector x2(b), reference2(b);
    ok = ok && lu.solve(scaled, 1, reference2, b) &&
         eliminated.solve(scaled, 1, x2, b);

    SparseDirect::Vector residual(b);
    matrix.vmult(residual, x);
    residual -= b;
    SparseDirect::Vector difference(x);
    difference -= reference;
    SparseDirect::Vector difference2(x2);
    difference2 -= reference2;
    const double error = std::max(difference.l2_norm() / reference.l2_norm(),
                                  difference2.l2_norm() / reference2.l2_norm());
    const double relative_residual = residual.l2_norm() / b.l2_norm();
    std::cout << name << ": " << eliminated.method() << ", "
              << eliminated.refinements()
              << " refinement steps, difference to LU " << error
              << ", residual " << relative_residual << std::endl;
    // "eliminated": either factorization of the eliminated matrix (the
    // symmetry test is relative to its largest entry, the penalty's, so
    // small unsymmetric terms may still go to CHOLMOD: the refinement
    // removes them with the regularization).
    const bool method_ok = expected_method == "eliminated" ?
                             eliminated.method().find(
                               "multipliers eliminated") != std::string::npos :
                             eliminated.method() == expected_method;
    if (!ok || !(error < 1e-10) || !(relative_residual < 1e-12) || !method_ok)
    {
      std::cout << "  FAILED (expected " << expected_method << ")" << std::endl;
      return false;
    }
    return true;
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::mt19937                     random(7);
  bool                             ok = true;
  const auto O = Node::open, C = Node::closed, S = Node::stick;
  ok &= check("frictionless, anchored",
              200,
              {O, C, C, O, C, C, C, O},
              true,
              false,
              false,
              "CHOLMOD, multipliers eliminated",
              random);
  ok &= check("frictionless with geometric terms",
              200,
              {O, C, C, O, C, C, C, O},
              true,
              false,
              true,
              "eliminated",
              random);
  ok &= check("frictionless, held by contact only",
              200,
              {C, C, O, C, O, O, C, C},
              false,
              false,
              false,
              "CHOLMOD, multipliers eliminated",
              random);
  ok &= check("stick, unsymmetric: LU of the whole system",
              200,
              {S, C, O, S, S, C, O, S},
              true,
              false,
              true,
              "UMFPACK",
              random);
  ok &= check("multipliers coupled across nodes: LU",
              200,
              {C, C, O, C, O, O, C, C},
              true,
              true,
              false,
              "UMFPACK",
              random);
  std::cout << (ok ? "OK" : "FAILED") << std::endl;
  return ok ? 0 : 1;
}
