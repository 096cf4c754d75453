/**
 * Unit test: the 2D mortar element's tangent (Sacado AD through the
 * segment projections, the clipped overlaps, D, M, the weighted nodal
 * normal and the enforcement's law) against central finite differences of
 * its residual. Random configurations: a slave node with one or two
 * segments (a curved slave surface), three or four master segments below
 * it (finer and coarser than the slave), overlaps clipped at the slave
 * segments' ends and at the master's end (standard basis there), dual and
 * standard basis, plane and axisymmetric (weight 2 pi r), straight (Q1)
 * and quadratic (Q2: curved segments with middle nodes, the slave node a
 * vertex of two segments or one, or a middle; the projections' Newton
 * steps differentiated), Q1 with the master's averaged normals (a bent
 * segment beyond each end of the master, whose nodes enter the normal);
 * frictionless,
 * stick and slip; with the penalty law and
 * with the Lagrange multiplier law (the rows and columns of the node's
 * multipliers included). Asserts a relative error below 1e-6 and that the
 * weights D, M reproduce the patch-test identity sum_k D_jk = sum_l M_jl
 * = w_j > 0 (checked through the residual of a uniform traction: the sum
 * of the forces vanishes).
 */

#include <tribos/contact/element/mortar_element.h>
#include <tribos/contact/enforcement/lagrange_multiplier.h>
#include <tribos/contact/enforcement/penalty.h>

#include <cmath>
#include <iostream>
#include <random>
#include <vector>

#include "mortar_check.h"

using namespace tribos;

/**
 * A random mortar element input of @p sample (its kinds: quadratic,
 * smoothed master, axisymmetric, ... by the sample number); @p quadratic,
 * @p smoothed and the slave's segment length @p h_slave are set.
 */
MortarInput
random_input(std::mt19937                           &random,
             std::uniform_real_distribution<double> &u,
             const unsigned int                      sample,
             bool                                   &quadratic,
             bool                                   &smoothed,
             double                                 &h_slave)
{
  // Slave: node j at the origin, neighbours left and right (slave body
  // above, so the segments run right to left for an outward normal
  // pointing down); sometimes only one segment (an end of the slave).
  // Every other pair of samples is quadratic (Q2): curved segments with
  // middle nodes, node j a vertex of two segments, of one, or a middle.
  MortarInput input;
  quadratic                 = (sample / 2) % 2 == 1;
  h_slave                   = 0.5 + 0.3 * u(random);
  input.xs[0]               = {{0.05 * u(random), 0.02 * u(random), 0}};
  input.xs[1]               = {{h_slave, 0.1 * h_slave + 0.05 * u(random), 0}};
  input.xs[2]               = {{-h_slave + 0.05 * u(random), 0.1 * h_slave, 0}};
  const bool one_segment    = sample % 7 == 0;
  input.n_slave_nodes       = one_segment ? 2 : 3;
  input.n_slave_segments    = one_segment ? 1 : 2;
  input.slave_segment[0][0] = 1;
  input.slave_segment[0][1] = 0;
  input.slave_segment[1][0] = 0;
  input.slave_segment[1][1] = 2;
  // A middle node between a and b, off the chord by up to 5 % of it.
  const auto middle = [&](const Vec3<double> &a, const Vec3<double> &b)
  {
    const Vec3<double> chord = b - a;
    const Vec3<double> off{{-chord[1], chord[0], 0}};
    return scale(0.5, a + b) + scale(0.05 * u(random), off) +
           scale(0.03 * u(random), chord);
  };
  if (quadratic)
  {
    input.shape             = FaceShape::of<Segment3>();
    const unsigned int kind = (sample / 4) % 3;
    if (kind == 0 && !one_segment)
    {
      input.xs[3]               = middle(input.xs[1], input.xs[0]);
      input.xs[4]               = middle(input.xs[0], input.xs[2]);
      input.n_slave_nodes       = 5;
      input.slave_segment[0][2] = 3;
      input.slave_segment[1][2] = 4;
    }
    else if (kind == 1 || one_segment)
    {
      input.xs[2]               = middle(input.xs[1], input.xs[0]);
      input.n_slave_nodes       = 3;
      input.n_slave_segments    = 1;
      input.slave_segment[0][2] = 2;
    }
    else
    {
      // j is the middle of the segment from node 1 to node 2.
      input.xs[0]               = middle(input.xs[1], input.xs[2]);
      input.n_slave_nodes       = 3;
      input.n_slave_segments    = 1;
      input.slave_segment[0][0] = 1;
      input.slave_segment[0][1] = 2;
      input.slave_segment[0][2] = 0;
    }
  }

  // Master: a polyline below, left to right (body below, normal up),
  // spacing finer or coarser than the slave; sometimes ending under
  // the slave segment (partial coverage). Quadratic: a middle node on
  // each segment, after the vertices.
  const unsigned int n_master = 3 + sample % 2;
  const double       h_master = (sample % 3 == 0 ? 0.4 : 1.0) * h_slave;
  const double start = -0.5 * n_master * h_master + 0.3 * h_master * u(random);
  const bool   short_master = sample % 5 == 0;
  input.n_master_nodes      = n_master + 1;
  input.n_master_segments   = n_master;
  for (unsigned int l = 0; l <= n_master; ++l)
    input.xm[l] = {{start + l * h_master * (short_master ? 0.6 : 1.),
                    0.01 * u(random) - 0.02 * std::abs(u(random)),
                    0}};
  for (unsigned int m = 0; m < n_master; ++m)
    input.master_segment[m] = {{m, m + 1}};
  if (quadratic)
    for (unsigned int m = 0; m < n_master; ++m)
    {
      input.xm[n_master + 1 + m] = middle(input.xm[m], input.xm[m + 1]);
      input.master_segment[m][2] = n_master + 1 + m;
      ++input.n_master_nodes;
    }
  // Three Q1 samples in seven: the master's averaged normals (Master
  // smoothing), with a bent segment beyond each end of the polyline.
  smoothed = !quadratic && sample % 7 < 3;
  if (smoothed)
  {
    const unsigned int left = n_master + 1, right = n_master + 2;
    input.xm[left] = {
      {input.xm[0][0] - h_master, 0.2 * h_master * u(random), 0}};
    input.xm[right] = {
      {input.xm[n_master][0] + h_master, 0.2 * h_master * u(random), 0}};
    input.n_master_nodes += 2;
    input.smoothed_master = true;
    for (unsigned int m = 0; m < n_master; ++m)
    {
      input.master_beyond[m][0] = m == 0 ? left : m - 1;
      input.master_beyond[m][1] = m + 1 == n_master ? right : m + 2;
    }
  }
  for (unsigned int i = 0; i < input.n_slave_nodes; ++i)
    for (unsigned int d = 0; d < 2; ++d)
      input.xs_old[i][d] = input.xs[i][d] + 0.01 * u(random);
  for (unsigned int l = 0; l < input.n_master_nodes; ++l)
    for (unsigned int d = 0; d < 2; ++d)
      input.xm_old[l][d] = input.xm[l][d] + 0.01 * u(random);
  input.dual = sample % 3 != 2;
  // Every fourth: axisymmetric (x = r > 0), weight 2 pi r in every
  // integral and in the dual functions.
  input.axisymmetric = sample % 4 == 1;
  if (input.axisymmetric)
  {
    for (unsigned int i = 0; i < input.n_slave_nodes; ++i)
    {
      input.xs[i][0] += 3.;
      input.xs_old[i][0] += 3.;
    }
    for (unsigned int l = 0; l < input.n_master_nodes; ++l)
    {
      input.xm[l][0] += 3.;
      input.xm_old[l][0] += 3.;
    }
  }
  input.min_weight = 0;
  // Shift the slave up or down: open or closed.
  const double lift = -0.03 + 0.04 * u(random);
  for (unsigned int i = 0; i < input.n_slave_nodes; ++i)
    input.xs[i][1] += lift;

  return input;
}



int
main()
{
  std::mt19937                           random(20261123);
  std::uniform_real_distribution<double> u(-1, 1);
  static const Parameters::Contact       parameters{};
  static const Penalty<2>                penalty;
  static const LagrangeMultiplier<2>     multipliers(parameters);

  bool         ok          = true;
  double       worst_error = 0, worst_balance = 0;
  unsigned int n_checked = 0, n_quadratic = 0, n_smoothed = 0,
               n_status[4] = {0, 0, 0, 0};
  for (unsigned int sample = 0; sample < 4000; ++sample)
  {
    const bool            with_multipliers = sample % 2 == 1;
    const Enforcement<2> &enforcement =
      with_multipliers ? static_cast<const Enforcement<2> &>(multipliers) :
                         static_cast<const Enforcement<2> &>(penalty);

    bool              quadratic, smoothed;
    double            h_slave;
    const MortarInput input =
      random_input(random, u, sample, quadratic, smoothed, h_slave);
    ContactLaw law;
    law.normal_penalty       = 1e3;
    law.tangential_penalty   = (sample % 4 == 0 ? 1e5 : 1e2);
    law.friction_coefficient = sample % 6 == 0 ? 0. : 0.3;
    NodeState history;
    history.result.status   = ContactStatus::stick;
    history.result.normal   = {{0, 1, 0}};
    history.result.traction = {{2 * u(random), 0, 0}};
    history.point           = {
                {input.xs_old[0][0] + 0.01 * u(random), input.xs_old[0][1] - 0.01, 0}};
    const Vec3<double> lambda{{3 * u(random), 5 + 3 * u(random), 0}};

    SlaveInput slave;
    slave.position   = input.xs[0];
    slave.committed  = &history;
    slave.law        = law;
    slave.area       = h_slave;
    slave.consistent = true;
    slave.unknowns   = with_multipliers ? &lambda : nullptr;

    const MortarCheck check =
      check_mortar_element<2, Mortar2D>(input,
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
    if (quadratic)
      ++n_quadratic;
    if (smoothed)
      ++n_smoothed;
    const double relative = check.relative_error;
    worst_error           = std::max(worst_error, relative);
    if (relative > 1e-6)
    {
      ok = false;
      std::cout << "sample " << sample << ": tangent error " << relative
                << " (status " << static_cast<int>(status)
                << (with_multipliers ? ", multipliers" : ", penalty")
                << (input.dual ? ", dual" : ", standard")
                << (quadratic ? ", quadratic" : "")
                << (smoothed ? ", smoothed master" : "") << ")\n";
    }
  }
  std::cout << "checked " << n_checked << " mortar elements (" << n_quadratic
            << " quadratic, " << n_smoothed
            << " with the master's averaged normals; open " << n_status[0]
            << ", stick " << n_status[1] << ", slip " << n_status[2]
            << ", frictionless " << n_status[3]
            << "); worst relative tangent error " << worst_error
            << ", worst force balance " << worst_balance << "\n";
  if (n_checked < 500 || n_quadratic < 200 || n_smoothed < 200 ||
      n_status[1] < 50 || n_status[2] < 50 || n_status[3] < 20)
  {
    std::cout << "FAILED: too few elements of some kind were checked\n";
    ok = false;
  }
  if (worst_balance > 1e-10)
  {
    std::cout << "FAILED: the forces of a mortar element do not balance\n";
    ok = false;
  }
  std::cout << (ok ? "OK" : "FAILED") << std::endl;
  return ok ? 0 : 1;
}
