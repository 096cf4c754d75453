/**
 * What the unit tests inp_file, inp_file_node_order and inp_file_errors
 * share: reading a deck given as text, the expected failure of reading
 * one, the 2D deck of two bodies, points of a mesh, and every cut of a
 * deck.
 */

#ifndef tribos_tests_inp_file_cases_h
#define tribos_tests_inp_file_cases_h

#include <tribos/scene/inp_file.h>

#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "reader_check.h"

namespace inp_file_cases
{
  inline tribos::MshFile
  read(const std::string    &name,
       const std::string    &text,
       const tribos::InpIds &ids = tribos::InpIds())
  {
    try
    {
      return tribos::read_inp_file(reader_check::write(name + ".inp", text),
                                   ids);
    }
    catch (const std::exception &e)
    {
      reader_check::check(false, name + ": " + e.what());
      return tribos::MshFile();
    }
  }

  /** Reading @p file must fail in @p in (default: @p file) at @p line with
   * a message that has @p expected in it. */
  inline void
  expect_error_in(const std::string    &name,
                  const std::string    &file,
                  const std::size_t     line,
                  const std::string    &expected,
                  const tribos::InpIds &ids = tribos::InpIds(),
                  std::string           in  = "")
  {
    reader_check::expect_error_in(
      name,
      [&]() { tribos::read_inp_file(file, ids); },
      in.empty() ? file : in,
      line,
      expected);
  }

  inline void
  expect_error(const std::string    &name,
               const std::string    &text,
               const std::size_t     line,
               const std::string    &expected,
               const tribos::InpIds &ids = tribos::InpIds())
  {
    expect_error_in(name,
                    reader_check::write(name + ".inp", text),
                    line,
                    expected,
                    ids);
  }

  // The 2D deck of the first test: a 2 x 1 plate (bodies PLATE, elements
  // 1-2) under a 1 x 1 block (BLOCK, element 3) that shares no node.
  inline const std::string two_bodies = R"(*HEADING
two bodies
** the plate
*NODE
1, 0., 0.
2, 1., 0.
3, 2., 0.
4, 0., 1.
5, 1., 1.
6, 2., 1.
*node
11, 0.5, 1.0
12, 1.5, 1.0
13, 1.5, 2.0
14, 0.5, 2.0

*Element, type=CPE4R, elset=Plate
1, 1, 2, 5, 4
2, 2, 3, 6, 5
* ELEMENT , TYPE = CPS4 , ELSET = BLOCK
3, 11, 12, 13, 14
*NSET, NSET=BOTTOM
1, 2,
3
*SURFACE, NAME=TOP_OF_PLATE
PLATE, S3
*Surface, name=BLOCK_BOTTOM, type=ELEMENT
3, S1
*MATERIAL, NAME=STEEL
*ELASTIC
210000, 0.3
*STEP
*STATIC
*BOUNDARY
BOTTOM, 1, 2
*END STEP
)";

  using Point = std::array<double, 3>;

  inline Point
  position(const tribos::MshFile &mesh, const std::size_t node)
  {
    return mesh.nodes[node].x;
  }

  inline bool
  close(const Point &a, const Point &b)
  {
    return std::abs(a[0] - b[0]) + std::abs(a[1] - b[1]) +
             std::abs(a[2] - b[2]) <
           1e-12;
  }

  inline Point
  midpoint(const Point &a, const Point &b)
  {
    return {{(a[0] + b[0]) / 2, (a[1] + b[1]) / 2, (a[2] + b[2]) / 2}};
  }

  /** The boundary elements (dim below the cells') of physical @p id. */
  inline std::vector<const tribos::MshFile::Element *>
  boundary(const tribos::MshFile &mesh, const unsigned int dim, const int id)
  {
    std::vector<const tribos::MshFile::Element *> result;
    for (const auto &e : mesh.elements)
      if (e.dim + 1 == dim && e.physical == id)
        result.push_back(&e);
    return result;
  }

  /** The name of physical group (@p dim, @p id), "" if none. */
  inline std::string
  physical_name(const tribos::MshFile &mesh,
                const unsigned int     dim,
                const int              id)
  {
    for (const auto &p : mesh.physical_names)
      if (p.dim == dim && p.tag == id)
        return p.name;
    return "";
  }



  /** Every cut of @p text at a line end or mid-line must read or give an
   * MshError: no crash, no other exception. */
  inline void
  test_cuts(const std::string &name, const std::string &text)
  {
    std::size_t n_cuts = 0, n_read = 0;
    for (std::size_t at = 0; at < text.size(); at += 1 + at % 7)
    {
      const std::string file =
        reader_check::write("cut.inp", text.substr(0, at));
      try
      {
        tribos::read_inp_file(file);
        ++n_read;
      }
      catch (const tribos::MshError &)
      {
      }
      catch (const std::exception &e)
      {
        reader_check::check(false,
                            name + " cut at " + std::to_string(at) + ": " +
                              e.what());
      }
      ++n_cuts;
    }
    reader_check::check(n_cuts > 50 && n_read > 0,
                        name + ": " + std::to_string(n_cuts) + " cuts, " +
                          std::to_string(n_read) + " read");
  }
} // namespace inp_file_cases

#endif
