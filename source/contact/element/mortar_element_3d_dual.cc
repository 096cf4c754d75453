// The dual functions of the 3D mortar element (Mortar3D): the modified
// basis of quadratic faces and the row a slave face carries in Phi = A Ntilde.

#include <tribos/contact/element/mortar_integrals.h>

#include <array>
#include <cmath>
#include <vector>

#include "mortar_element_3d_internal.h"

namespace tribos
{
  using namespace internal::Mortar3DImplementation;

  namespace
  {
    /**
     * The basis the dual functions of a face of @p n nodes are
     * biorthogonal to, as Ntilde = T N: the face's own on a linear face
     * (T = 1); on the quadratic triangle the modified basis of
     * TriangleFace::modified_basis_alpha, on the nine-node quadrilateral
     * the tensor product of the quadratic segment's with that alpha. The
     * quadratic vertex functions integrate to zero over a flat face, so dual
     * functions biorthogonal to them do not exist; the modified ones are
     * positive on average and still sum to one.
     */
    void
    modified_basis(const unsigned int n,
                   double (&T)[max_face_nodes][max_face_nodes])
    {
      for (unsigned int i = 0; i < max_face_nodes; ++i)
        for (unsigned int k = 0; k < max_face_nodes; ++k)
          T[i][k] = (i == k && i < n) ? 1. : 0.;
      if (n == 9)
      {
        // The tensor product of the quadratic segment's modified functions
        // (ends N_e + alpha N_m, middle (1 - 2 alpha) N_m) with the same
        // alpha: the biquadratic vertex functions integrate to only A/36
        // (the centre's 4A/9), and the vertices' multipliers, divided by so
        // little, scatter on distorted faces (the 3D press fit of
        // tests/verification/curved_meshes.py: 8.2 % RMS at the vertices, 2.6 %
        // with this basis, whose integrals are 9A/100 at the vertices, 3A/25 at
        // the edge middles and 4A/25 at the centre of a flat face of area
        // A).
        const double           alpha     = TriangleFace::modified_basis_alpha;
        const double           T_1[3][3] = {{1., 0., alpha},
                                            {0., 1., alpha},
                                            {0., 0., 1. - 2. * alpha}};
        constexpr unsigned int at_1[9]   = {0, 1, 0, 1, 2, 2, 0, 1, 2},
                               at_2[9]   = {0, 0, 1, 1, 0, 1, 2, 2, 2};
        for (unsigned int i = 0; i < 9; ++i)
          for (unsigned int k = 0; k < 9; ++k)
            T[i][k] = T_1[at_1[i]][at_1[k]] * T_1[at_2[i]][at_2[k]];
        return;
      }
      if (n != 6)
        return;
      const double alpha = TriangleFace::modified_basis_alpha;
      for (unsigned int v = 0; v < 3; ++v)
      {
        T[v][3 + v]           = alpha; // edge v, v + 1
        T[v][3 + (v + 2) % 3] = alpha; // edge v - 1, v
        T[3 + v][3 + v]       = 1. - 2. * alpha;
      }
    }
  } // namespace



  namespace internal::Mortar3DImplementation
  {
    void
    carried_row(const MortarInput3D &input,
                const unsigned int   f,
                const Piece         *pieces,
                const unsigned int   n_pieces,
                const Plane<AD>     *planes,
                const AD            &theta,
                AD                  *a)
    {
      const AD           zero(0.);
      const unsigned int n = input.slave_face[f].n;
      double             T[max_face_nodes][max_face_nodes];
      modified_basis(n, T);
      // Scratch of this thread (AD numbers zero their derivatives when
      // constructed: some 200 of them per call).
      static thread_local struct
      {
        AD coefficients[max_face_nodes]; // of Phi in the modified basis
        AD mass[max_face_nodes][max_face_nodes];
        AD row_sum[max_face_nodes];
        AD lower[max_face_nodes][max_face_nodes];
        AD y[max_face_nodes];
      } scratch;
      auto &coefficients = scratch.coefficients;
      for (unsigned int i = 0; i < n; ++i)
        coefficients[i] = zero;
      if (theta.val() <= 0)
        for (unsigned int c = 0; c < input.n_carriers[f]; ++c)
          coefficients[input.carriers[f][c].first] +=
            input.carriers[f][c].second;
      else
      {
        // The mass matrix, exactly on flat pieces: 2 x 2 Gauss on a
        // bilinear quadrilateral, 3 x 3 on the pieces of a nine-node one
        // (degree 4 in each direction, 5 with the Jacobian), the 7-point
        // rule on a triangle piece (degree 4 on the quadratic triangle).
        auto &mass = scratch.mass;
        for (unsigned int i = 0; i < n; ++i)
          for (unsigned int k = 0; k < n; ++k)
            mass[i][k] = zero;
        // (xi_1, xi_2, weight) in the piece's coordinates.
        using Rule = std::vector<std::array<double, 3>>;
        static const Rule quadrilateral_rule = []()
        {
          const double g = 1. / std::sqrt(3.);
          return Rule{{{-g, -g, 1.}},
                      {{g, -g, 1.}},
                      {{-g, g, 1.}},
                      {{g, g, 1.}}};
        }();
        static const Rule biquadratic_rule = []()
        {
          const double g    = std::sqrt(0.6);
          const double x[3] = {-g, 0., g}, w[3] = {5. / 9., 8. / 9., 5. / 9.};
          Rule         rule;
          for (unsigned int b = 0; b < 3; ++b)
            for (unsigned int a = 0; a < 3; ++a)
              rule.push_back({{x[a], x[b], w[a] * w[b]}});
          return rule;
        }();
        static const Rule triangle_piece_rule = []()
        {
          Rule rule;
          for (const TrianglePoint &t : triangle_rule)
            rule.push_back({{t.l[1], t.l[2], 0.5 * t.weight}});
          return rule;
        }();
        for (unsigned int s = 0; s < n_pieces; ++s)
        {
          const Piece &piece = pieces[s];
          const Rule  &rule  = piece.n == 3 ? triangle_piece_rule :
                               n == 9       ? biquadratic_rule :
                                              quadrilateral_rule;
          for (const auto &point : rule)
          {
            const double x[2] = {point[0], point[1]};
            double N_piece[4], dN[max_face_nodes][2], xi[2], N[max_face_nodes],
              Nt[max_face_nodes];
            face_shape(piece.n, x, N_piece, dN);
            AD J[2][2] = {{zero, zero}, {zero, zero}};
            for (unsigned int k = 0; k < piece.n; ++k)
              for (unsigned int r = 0; r < 2; ++r)
                for (unsigned int c = 0; c < 2; ++c)
                  J[r][c] += dN[k][c] * planes[s].P[k][r];
            const AD det = J[0][0] * J[1][1] - J[0][1] * J[1][0];
            face_coordinates(piece, x, xi);
            face_shape(n, xi, N, dN);
            for (unsigned int i = 0; i < n; ++i)
            {
              Nt[i] = 0.;
              for (unsigned int k = 0; k < n; ++k)
                Nt[i] += T[i][k] * N[k];
            }
            for (unsigned int i = 0; i < n; ++i)
              for (unsigned int k = 0; k < n; ++k)
                mass[i][k] += (point[2] * Nt[i] * Nt[k]) * det;
          }
        }
        auto &row_sum = scratch.row_sum;
        for (unsigned int i = 0; i < n; ++i)
        {
          row_sum[i] = zero;
          for (unsigned int k = 0; k < n; ++k)
            row_sum[i] += mass[i][k];
        }
        // M_e = L U (symmetric positive definite: no pivoting).
        auto &lower = scratch.lower;
        for (unsigned int p = 0; p < n; ++p)
          for (unsigned int i = p + 1; i < n; ++i)
          {
            lower[i][p] = mass[i][p] / mass[p][p];
            for (unsigned int k = p; k < n; ++k)
              mass[i][k] -= lower[i][p] * mass[p][k];
          }
        for (unsigned int c = 0; c < input.n_carriers[f]; ++c)
        {
          const auto [j_local, weight] = input.carriers[f][c];
          // y = M_e^-1 e_j.
          auto &y = scratch.y;
          for (unsigned int k = 0; k < n; ++k)
            y[k] = zero;
          y[j_local] = 1.;
          for (unsigned int p = 0; p < n; ++p)
            for (unsigned int i = p + 1; i < n; ++i)
              y[i] -= lower[i][p] * y[p];
          for (unsigned int p = n; p-- > 0;)
          {
            for (unsigned int k = p + 1; k < n; ++k)
              y[p] -= mass[p][k] * y[k];
            y[p] /= mass[p][p];
          }
          for (unsigned int k = 0; k < n; ++k)
            coefficients[k] += weight * (theta * row_sum[j_local] * y[k] +
                                         (k == j_local ? 1. - theta : zero));
        }
      }
      // From the modified basis to the face's functions: a = T^T c.
      for (unsigned int m = 0; m < n; ++m)
        for (unsigned int k = 0; k < n; ++k)
          if (T[m][k] != 0.)
            a[k] += coefficients[m] * T[m][k];
    }
  } // namespace internal::Mortar3DImplementation
} // namespace tribos
