// ctest: labels slow
/**
 * Unit test: the 3D mortar element's tangent (Sacado AD through the
 * auxiliary planes, the polygon clipping, the inverse bilinear maps, D, M,
 * the dual functions, the weighted nodal normal and the enforcement's law)
 * against central finite differences of its residual. Random
 * configurations: a slave node with its four faces (a warped 3 x 3 patch
 * of nodes), a grid of 3 x 3 or 4 x 4 master faces below it, finer and
 * coarser than the slave, sometimes ending under the slave patch (partial
 * coverage: the blend towards the standard basis), dual and standard
 * basis; frictionless, stick and slip; with the penalty law and with the
 * Lagrange multiplier law (the rows and columns of the node's multipliers
 * included). Then the same with each quadrilateral split into two
 * triangles (the faces of tetrahedra) on the slave side, the master side
 * or both, with six-node triangles on both sides (P2 tetrahedra,
 * curved: the modified dual basis and the integration on the faces'
 * four flat pieces), and with nine-node quadrilaterals on both sides (Q2
 * hexahedra, curved: four bilinear pieces per face). Asserts a relative error
 * below 1e-6 and that the forces of the element balance (sum_k D_jk = sum_l
 * M_jl).
 */

#include <tribos/contact/element/mortar_element_3d.h>
#include <tribos/contact/enforcement/lagrange_multiplier.h>
#include <tribos/contact/enforcement/penalty.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <random>
#include <vector>

#include "mortar_check.h"

using namespace tribos;

/**
 * The rest of a random input of @p sample once its nodes and faces are
 * set: positions at the last converged step near the current ones, the
 * basis, and the slave shifted up or down (open or closed).
 */
void
finish_input(std::mt19937                           &random,
             std::uniform_real_distribution<double> &u,
             const unsigned int                      sample,
             MortarInput3D                          &input)
{
  for (unsigned int i = 0; i < input.n_slave_nodes; ++i)
    for (unsigned int d = 0; d < 3; ++d)
      input.xs_old[i][d] = input.xs[i][d] + 0.01 * u(random);
  for (unsigned int l = 0; l < input.n_master_nodes; ++l)
    for (unsigned int d = 0; d < 3; ++d)
      input.xm_old[l][d] = input.xm[l][d] + 0.01 * u(random);
  input.dual        = sample % 3 != 2;
  input.min_weight  = 0;
  const double lift = -0.03 + 0.04 * u(random);
  for (unsigned int i = 0; i < input.n_slave_nodes; ++i)
    input.xs[i][2] += lift;
}



/**
 * A random 3D mortar element input of @p sample (its kinds by the sample
 * number); @p carries (node j carries half of a neighbour's function),
 * @p short_master (the master ends under the slave patch) and the slave's
 * face size @p h_slave are set. With @p slave_triangles or
 * @p master_triangles each quadrilateral of that side is two triangles.
 */
MortarInput3D
random_input(std::mt19937                           &random,
             std::uniform_real_distribution<double> &u,
             const unsigned int                      sample,
             bool                                   &carries,
             bool                                   &short_master,
             double                                 &h_slave,
             const bool                              slave_triangles  = false,
             const bool                              master_triangles = false)
{
  // The quadrilateral (lexicographic, counter-clockwise 0 1 3 2) as itself
  // or as the triangles (0, 1, 3) and (0, 3, 2), with the same normal.
  const auto add_faces = [](const std::array<unsigned int, 4> &quad,
                            const bool                         split,
                            MortarFace3D                      *faces,
                            unsigned int                      &n_faces)
  {
    if (!split)
    {
      faces[n_faces].nodes = {{quad[0], quad[1], quad[2], quad[3], 0, 0}};
      faces[n_faces++].n   = 4;
      return;
    }
    faces[n_faces].nodes = {{quad[0], quad[1], quad[3], 0, 0, 0}};
    faces[n_faces++].n   = 3;
    faces[n_faces].nodes = {{quad[0], quad[3], quad[2], 0, 0, 0}};
    faces[n_faces++].n   = 3;
  };
  // Slave: a 3 x 3 patch of nodes, node j in the middle (local 0), the
  // body above: vertex order (y before x) so that the faces' normal
  // points down, out of the slave.
  MortarInput3D input;
  h_slave = 0.5 + 0.2 * u(random);
  unsigned int local[3][3], next = 1;
  for (unsigned int i = 0; i < 3; ++i)
    for (unsigned int j = 0; j < 3; ++j)
    {
      const unsigned int n = (i == 1 && j == 1) ? 0 : next++;
      local[i][j]          = n;
      input.xs[n]          = {{(i - 1.) * h_slave + 0.05 * h_slave * u(random),
                               (j - 1.) * h_slave + 0.05 * h_slave * u(random),
                               0.03 * h_slave * u(random)}};
    }
  input.n_slave_nodes = 9;
  input.n_slave_faces = 0;
  for (unsigned int i = 0; i < 2; ++i)
    for (unsigned int j = 0; j < 2; ++j)
      add_faces(
        {{local[i][j], local[i][j + 1], local[i + 1][j], local[i + 1][j + 1]}},
        slave_triangles,
        input.slave_face,
        input.n_slave_faces);
  // Node j's multiplier function; in some samples plus half of a
  // neighbour's, as when j carries a hanging node (Phi_j + 0.5 Phi_h).
  carries                    = sample % 7 == 3;
  const unsigned int hanging = local[1][2];
  for (unsigned int f = 0; f < input.n_slave_faces; ++f)
  {
    input.n_carriers[f] = 0;
    for (unsigned int v = 0; v < input.slave_face[f].n; ++v)
    {
      if (input.slave_face[f][v] == 0)
        input.carriers[f][input.n_carriers[f]++] = {v, 1.};
      if (carries && input.slave_face[f][v] == hanging)
        input.carriers[f][input.n_carriers[f]++] = {v, 0.5};
    }
  }

  // Master: n x n faces below, lexicographic (normal up), finer or
  // coarser than the slave, sometimes shorter than the slave patch.
  const unsigned int n_master = 3 + sample % 2;
  const double       h_master = (sample % 3 == 0 ? 0.55 : 0.9) * h_slave;
  short_master                = sample % 5 == 0;
  const double reach          = short_master ? 0.6 : 1.;
  const double start_x =
    -0.5 * n_master * h_master * reach + 0.2 * h_master * u(random);
  const double start_y =
    -0.5 * n_master * h_master + 0.2 * h_master * u(random);
  input.n_master_nodes = (n_master + 1) * (n_master + 1);
  for (unsigned int b = 0; b <= n_master; ++b)
    for (unsigned int a = 0; a <= n_master; ++a)
      input.xm[b * (n_master + 1) + a] = {
        {start_x + a * h_master * reach + 0.05 * h_master * u(random),
         start_y + b * h_master + 0.05 * h_master * u(random),
         0.01 * u(random) - 0.02 * std::abs(u(random))}};
  input.n_master_faces = 0;
  for (unsigned int b = 0; b < n_master; ++b)
    for (unsigned int a = 0; a < n_master; ++a)
    {
      const unsigned int c = b * (n_master + 1) + a;
      add_faces({{c, c + 1, c + n_master + 1, c + n_master + 2}},
                master_triangles,
                input.master_face,
                input.n_master_faces);
    }
  finish_input(random, u, sample, input);

  return input;
}


/**
 * As random_input(), with quadratic faces on both sides, curved (their
 * middle nodes off the chords): six-node triangles (the faces of P2
 * tetrahedra), or with @p nine_node biquadratic quadrilaterals (Q2
 * hexahedra).
 */
MortarInput3D
random_quadratic_input(std::mt19937                           &random,
                       std::uniform_real_distribution<double> &u,
                       const unsigned int                      sample,
                       bool                                   &short_master,
                       double                                 &h_slave,
                       const bool                              nine_node)
{
  // The quadrilateral with corners (g0, g1, g2, g3) (lexicographic) of a
  // grid of nodes (the middles at the averaged grid indices) as the
  // six-node triangles (0, 1, 3) and (0, 3, 2), or as itself with its
  // edge middles (0-1, 2-3, 0-2, 1-3) and centre.
  const auto add_faces =
    [nine_node](const std::array<std::array<unsigned int, 2>, 4> &g,
                const auto                                       &number,
                MortarFace3D                                     *faces,
                unsigned int                                     &n_faces)
  {
    const auto middle = [&](const unsigned int a, const unsigned int b)
    {
      return number((g[a][0] + g[b][0]) / 2, (g[a][1] + g[b][1]) / 2);
    };
    if (nine_node)
    {
      MortarFace3D &face = faces[n_faces++];
      face.n             = 9;
      for (unsigned int v = 0; v < 4; ++v)
        face.nodes[v] = number(g[v][0], g[v][1]);
      face.nodes[4] = middle(0, 1);
      face.nodes[5] = middle(2, 3);
      face.nodes[6] = middle(0, 2);
      face.nodes[7] = middle(1, 3);
      face.nodes[8] = middle(0, 3);
      return;
    }
    for (const std::array<unsigned int, 3> t :
         {std::array<unsigned int, 3>{{0, 1, 3}},
          std::array<unsigned int, 3>{{0, 3, 2}}})
    {
      MortarFace3D &face = faces[n_faces++];
      face.n             = 6;
      for (unsigned int v = 0; v < 3; ++v)
      {
        const auto &a = g[t[v]], &b = g[t[(v + 1) % 3]];
        face.nodes[v]     = number(a[0], a[1]);
        face.nodes[3 + v] = number((a[0] + b[0]) / 2, (a[1] + b[1]) / 2);
      }
    }
  };
  MortarInput3D input;
  h_slave = 0.5 + 0.2 * u(random);
  unsigned int local[5][5], next = 1;
  for (unsigned int i = 0; i < 5; ++i)
    for (unsigned int j = 0; j < 5; ++j)
    {
      const unsigned int n = (i == 2 && j == 2) ? 0 : next++;
      local[i][j]          = n;
      input.xs[n] = {{(i - 2.) * 0.5 * h_slave + 0.03 * h_slave * u(random),
                      (j - 2.) * 0.5 * h_slave + 0.03 * h_slave * u(random),
                      0.03 * h_slave * u(random)}};
    }
  input.n_slave_nodes     = 25;
  input.n_slave_faces     = 0;
  const auto slave_number = [&](const unsigned int i, const unsigned int j)
  {
    return local[i][j];
  };
  for (unsigned int i = 0; i < 4; i += 2)
    for (unsigned int j = 0; j < 4; j += 2)
      add_faces({{{{i, j}}, {{i, j + 2}}, {{i + 2, j}}, {{i + 2, j + 2}}}},
                slave_number,
                input.slave_face,
                input.n_slave_faces);
  for (unsigned int f = 0; f < input.n_slave_faces; ++f)
  {
    input.n_carriers[f] = 0;
    for (unsigned int v = 0; v < input.slave_face[f].n; ++v)
      if (input.slave_face[f][v] == 0)
        input.carriers[f][input.n_carriers[f]++] = {v, 1.};
  }

  // 2 x 2 quadrilaterals of the master (9 x 9 master nodes would take the
  // finite differences minutes).
  const unsigned int n_master = 2, n_grid = 2 * n_master + 1;
  const double       h_master = (sample % 3 == 0 ? 0.9 : 1.2) * h_slave;
  short_master                = sample % 5 == 0;
  const double reach          = short_master ? 0.6 : 1.;
  const double start_x =
    -0.5 * n_master * h_master * reach + 0.2 * h_master * u(random);
  const double start_y =
    -0.5 * n_master * h_master + 0.2 * h_master * u(random);
  input.n_master_nodes = n_grid * n_grid;
  for (unsigned int b = 0; b < n_grid; ++b)
    for (unsigned int a = 0; a < n_grid; ++a)
      input.xm[b * n_grid + a] = {
        {start_x + 0.5 * a * h_master * reach + 0.03 * h_master * u(random),
         start_y + 0.5 * b * h_master + 0.03 * h_master * u(random),
         0.01 * u(random) - 0.02 * std::abs(u(random))}};
  const auto master_number = [&](const unsigned int a, const unsigned int b)
  {
    return b * n_grid + a;
  };
  input.n_master_faces = 0;
  for (unsigned int b = 0; b + 1 < n_grid; b += 2)
    for (unsigned int a = 0; a + 1 < n_grid; a += 2)
      add_faces({{{{a, b}}, {{a + 2, b}}, {{a, b + 2}}, {{a + 2, b + 2}}}},
                master_number,
                input.master_face,
                input.n_master_faces);
  finish_input(random, u, sample, input);
  return input;
}



int
main()
{
  std::mt19937                           random(20261124);
  std::uniform_real_distribution<double> u(-1, 1);
  static const Parameters::Contact       parameters{};
  static const Penalty<3>                penalty;
  static const LagrangeMultiplier<3>     multipliers(parameters);

  bool ok = true;
  // Round 0: quadrilaterals; round 1: triangles on the slave side, the
  // master side or both; round 2: six-node triangles on both sides; round
  // 3: nine-node quadrilaterals on both sides.
  for (unsigned int round = 0; round < 4; ++round)
  {
    double       worst_error = 0, worst_balance = 0;
    unsigned int n_checked = 0, n_status[4] = {0, 0, 0, 0}, n_partial = 0,
                 n_carrying      = 0;
    const unsigned int n_samples = round == 3 ? 8 :
                                   round == 2 ? 12 :
                                   round == 1 ? 30 :
                                                80;
    for (unsigned int sample = 0; sample < n_samples; ++sample)
    {
      const bool            slave_triangles  = round == 1 && sample % 3 != 1;
      const bool            master_triangles = round == 1 && sample % 3 != 0;
      const bool            with_multipliers = sample % 2 == 1;
      const Enforcement<3> &enforcement =
        with_multipliers ? static_cast<const Enforcement<3> &>(multipliers) :
                           static_cast<const Enforcement<3> &>(penalty);

      bool                carries = false, short_master = false;
      double              h_slave;
      const MortarInput3D input = round >= 2 ?
                                    random_quadratic_input(random,
                                                           u,
                                                           sample,
                                                           short_master,
                                                           h_slave,
                                                           round == 3) :
                                    random_input(random,
                                                 u,
                                                 sample,
                                                 carries,
                                                 short_master,
                                                 h_slave,
                                                 slave_triangles,
                                                 master_triangles);
      n_carrying += carries;
      n_partial += short_master;
      ContactLaw law;
      law.normal_penalty       = 1e3;
      law.tangential_penalty   = (sample % 4 == 0 ? 1e5 : 1e2);
      law.friction_coefficient = sample % 6 == 0 ? 0. : 0.3;
      NodeState history;
      history.result.status   = ContactStatus::stick;
      history.result.normal   = {{0, 0, 1}};
      history.result.traction = {{2 * u(random), 2 * u(random), 0}};
      history.point           = {{input.xs_old[0][0] + 0.01 * u(random),
                                  input.xs_old[0][1] + 0.01 * u(random),
                                  input.xs_old[0][2] - 0.01}};
      const Vec3<double> lambda{
        {3 * u(random), 3 * u(random), 5 + 3 * u(random)}};

      SlaveInput slave;
      slave.position   = input.xs[0];
      slave.committed  = &history;
      slave.law        = law;
      slave.area       = h_slave * h_slave;
      slave.consistent = true;
      slave.unknowns   = with_multipliers ? &lambda : nullptr;

      const MortarCheck check =
        check_mortar_element<3, Mortar3D>(input,
                                          slave,
                                          lambda,
                                          with_multipliers,
                                          enforcement);
      if (!check.paired)
        continue;
      const ContactStatus status = check.status;
      ++n_status[static_cast<int>(status)];
      worst_balance = std::max(worst_balance, check.balance);
      if (!check.checked)
        continue;
      ++n_checked;
      const double relative = check.relative_error;
      worst_error           = std::max(worst_error, relative);
      if (relative > 1e-6)
      {
        ok = false;
        std::cout << "sample " << sample << ": tangent error " << relative
                  << " (status " << static_cast<int>(status)
                  << (with_multipliers ? ", multipliers" : ", penalty")
                  << (input.dual ? ", dual" : ", standard")
                  << (short_master ? ", partial" : "")
                  << (carries ? ", carrying" : "")
                  << (slave_triangles ? ", slave triangles" : "")
                  << (master_triangles ? ", master triangles" : "") << ")\n";
      }
    }
    std::cout << "checked " << n_checked << " 3D mortar elements"
              << (round == 1 ? " on triangles" :
                  round == 2 ? " on six-node triangles" :
                  round == 3 ? " on nine-node quadrilaterals" :
                               "")
              << " (open " << n_status[0] << ", stick " << n_status[1]
              << ", slip " << n_status[2] << ", frictionless " << n_status[3]
              << "; partially covered " << n_partial
              << ", carrying a hanging node " << n_carrying
              << "); worst relative tangent error " << worst_error
              << ", worst force balance " << worst_balance << "\n";
    if (n_checked < n_samples / 2 || n_status[1] < n_samples / 10 ||
        n_status[2] < n_samples / 10 ||
        n_status[3] < std::min(3u, n_samples / 8) ||
        (round < 2 && n_carrying < n_samples / 16))
    {
      std::cout << "FAILED: too few elements of some kind were checked\n";
      ok = false;
    }
    if (worst_balance > 1e-10)
    {
      std::cout << "FAILED: the forces of a mortar element do not balance\n";
      ok = false;
    }
  }
  std::cout << (ok ? "OK" : "FAILED") << std::endl;
  return ok ? 0 : 1;
}
