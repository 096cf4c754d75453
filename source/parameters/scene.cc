#include <tribos/base/text.h>
#include <tribos/parameters/scene.h>
#include <tribos/scene/scene.h>

#include <deal.II/base/utilities.h>

namespace tribos
{
  namespace Parameters
  {
    using dealii::ParameterHandler;
    namespace Patterns = dealii::Patterns;

    namespace
    {
      /** Read a list entry and check that all values are positive. */
      std::vector<double>
      positive_list(ParameterHandler &prm, const std::string &entry)
      {
        const auto values = Text::parse_doubles(prm.get(entry), entry);
        for (const double v : values)
          AssertThrow(v > 0,
                      dealii::ExcMessage("Parameter <" + entry + "> = <" +
                                         prm.get(entry) +
                                         ">: every value must be > 0."));
        return values;
      }

      std::vector<unsigned int>
      cell_counts(ParameterHandler &prm, const std::string &entry)
      {
        const auto values = Text::parse_unsigned(prm.get(entry), entry);
        for (const unsigned int v : values)
          AssertThrow(v > 0,
                      dealii::ExcMessage("Parameter <" + entry + "> = <" +
                                         prm.get(entry) +
                                         ">: every cell count must be >= 1."));
        return values;
      }

      double
      positive(ParameterHandler &prm, const std::string &entry)
      {
        const double v = prm.get_double(entry);
        AssertThrow(v > 0,
                    dealii::ExcMessage("Parameter <" + entry + "> = <" +
                                       prm.get(entry) + ">: must be > 0."));
        return v;
      }
    } // namespace



    void
    Block::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Block");
      prm.declare_entry("Lower corner",
                        "0, 0, 0",
                        Patterns::Anything(),
                        "Coordinates x, y(, z); the first dim are used.");
      prm.declare_entry("Upper corner",
                        "1, 1, 1",
                        Patterns::Anything(),
                        "Coordinates x, y(, z); the first dim are used.");
      prm.declare_entry("Subdivisions",
                        "4, 4, 4",
                        Patterns::Anything(),
                        "Cells per direction before refinement.");
      prm.leave_subsection();
    }



    void
    Block::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Block");
      lower_corner = Text::parse_doubles(prm.get("Lower corner"),
                                         "Scene/Block/Lower corner");
      upper_corner = Text::parse_doubles(prm.get("Upper corner"),
                                         "Scene/Block/Upper corner");
      subdivisions = cell_counts(prm, "Subdivisions");
      prm.leave_subsection();
    }



    void
    TwoBlocks::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Two blocks");
      prm.declare_entry("Lower block size",
                        "1, 0.5, 1",
                        Patterns::Anything(),
                        "Extent per direction; the last used one (y in 2D, "
                        "z in 3D) is the height.");
      prm.declare_entry("Upper block size",
                        "1, 0.5, 1",
                        Patterns::Anything(),
                        "Extent per direction of the upper block.");
      prm.declare_entry("Lower subdivisions",
                        "4, 2, 4",
                        Patterns::Anything(),
                        "Cells per direction of the lower block.");
      prm.declare_entry("Upper subdivisions",
                        "3, 2, 3",
                        Patterns::Anything(),
                        "Cells per direction of the upper block; choose "
                        "counts different from the lower block for "
                        "non-matching interfaces.");
      prm.declare_entry("Gap",
                        "0",
                        Patterns::Double(0),
                        "Vertical distance between the blocks.");
      prm.declare_entry("Upper block offset",
                        "0",
                        Patterns::Double(),
                        "Shift of the upper block in x.");
      prm.declare_entry("Upper bottom radius",
                        "0",
                        Patterns::Double(0),
                        "0: flat. Otherwise the bottom of the upper block "
                        "is a circular arc (a cylinder in 3D, axis along "
                        "y) of this radius through the bottom corners, "
                        "lowest in the middle (the ironing punch); the "
                        "block keeps its height at the corners and the gap "
                        "is measured at the lowest point.");
      prm.declare_entry("Refinement box",
                        "",
                        Patterns::Anything(),
                        "Empty: none. Otherwise 'x0, y0(, z0) : x1, y1(, z1)', "
                        "the lower and upper corner of a box: the cells of "
                        "both blocks whose centre lies inside are refined "
                        "<Box refinements> times (hanging nodes where the "
                        "box ends).");
      prm.declare_entry("Box refinements",
                        "1",
                        Patterns::Integer(0, 6),
                        "Refinements of the cells in <Refinement box>.");
      prm.leave_subsection();
    }



    void
    TwoBlocks::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Two blocks");
      lower_size          = positive_list(prm, "Lower block size");
      upper_size          = positive_list(prm, "Upper block size");
      lower_subdivisions  = cell_counts(prm, "Lower subdivisions");
      upper_subdivisions  = cell_counts(prm, "Upper subdivisions");
      gap                 = prm.get_double("Gap");
      upper_offset        = prm.get_double("Upper block offset");
      upper_bottom_radius = prm.get_double("Upper bottom radius");
      AssertThrow(upper_bottom_radius == 0 ||
                    upper_bottom_radius > 0.5 * upper_size[0],
                  dealii::ExcMessage(
                    "Parameter <Scene/Two blocks/Upper bottom radius> = " +
                    std::to_string(upper_bottom_radius) +
                    " must be 0 or larger than half the upper block width."));
      box_refinements = prm.get_integer("Box refinements");
      const auto corners =
        dealii::Utilities::split_string_list(prm.get("Refinement box"), ':');
      AssertThrow(corners.empty() || corners.size() == 2,
                  dealii::ExcMessage(
                    "Parameter <Scene/Two blocks/Refinement box> = <" +
                    prm.get("Refinement box") +
                    ">: expected 'lower corner : upper corner', e.g. "
                    "'0, 0, 0 : 0.5, 1, 1'."));
      box_lower.clear();
      box_upper.clear();
      if (corners.size() == 2)
      {
        box_lower =
          Text::parse_doubles(corners[0], "Scene/Two blocks/Refinement box");
        box_upper =
          Text::parse_doubles(corners[1], "Scene/Two blocks/Refinement box");
        AssertThrow(box_lower.size() == box_upper.size(),
                    dealii::ExcMessage(
                      "Parameter <Scene/Two blocks/Refinement box> = <" +
                      prm.get("Refinement box") +
                      ">: both corners need the same number of coordinates."));
      }
      prm.leave_subsection();
    }



    void
    CylinderOverBlock::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Cylinder over block");
      prm.declare_entry("Radius", "1", Patterns::Double(), "Indenter radius.");
      prm.declare_entry("Gap",
                        "0",
                        Patterns::Double(0),
                        "Distance between the indenter's lowest point and "
                        "the block's top.");
      prm.declare_entry("Block width",
                        "4",
                        Patterns::Double(),
                        "2D: the block spans x in [-w/2, w/2]; 3D (quarter "
                        "model): x, y in [0, w/2].");
      prm.declare_entry("Block height",
                        "2",
                        Patterns::Double(),
                        "Depth of the block below y = 0 (2D) or z = 0 (3D).");
      prm.declare_entry("Block subdivisions",
                        "8, 4",
                        Patterns::Anything(),
                        "Cells in the horizontal and the vertical direction "
                        "(3D: both horizontal directions get the first).");
      prm.declare_entry("Indenter refinements",
                        "3",
                        Patterns::Integer(0, 8),
                        "Global refinements of the indenter's coarse mesh.");
      prm.declare_entry("With block",
                        "true",
                        Patterns::Bool(),
                        "false: the indenter alone (e.g. on a rigid plane).");
      prm.declare_entry(
        "Indenter shape",
        "lower half",
        Patterns::Selection("lower half|whole|meridian"),
        "lower half: the lower half of the cylinder (2D) or a quarter of the "
        "lower hemisphere (3D), loaded on its flat top (boundary 11). whole: "
        "the whole disc (2D only), e.g. a body in flight. meridian: the half "
        "disc x >= 0 (2D only), the meridian section of a whole sphere for "
        "Finite element/Axisymmetric = true, its axis boundary 12. The "
        "curved surface is boundary 10.");
      prm.declare_entry("Contact refinements",
                        "0",
                        Patterns::Integer(0, 10),
                        "Local refinements of the cells near the initial "
                        "contact point (hanging nodes; curved boundary kept "
                        "on its manifold).");
      prm.declare_entry("Refinement radius",
                        "0.25",
                        Patterns::Double(0),
                        "Cells that reach within this distance of the "
                        "initial contact point (a vertex or the centre "
                        "inside it), relative to the radius, are refined "
                        "in every contact refinement.");
      prm.leave_subsection();
    }



    void
    CylinderOverBlock::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Cylinder over block");
      radius               = positive(prm, "Radius");
      gap                  = prm.get_double("Gap");
      block_width          = positive(prm, "Block width");
      block_height         = positive(prm, "Block height");
      block_subdivisions   = cell_counts(prm, "Block subdivisions");
      indenter_refinements = prm.get_integer("Indenter refinements");
      with_block           = prm.get_bool("With block");
      indenter_shape       = prm.get("Indenter shape");
      contact_refinements  = prm.get_integer("Contact refinements");
      refinement_radius    = prm.get_double("Refinement radius");
      AssertThrow(block_subdivisions.size() >= 2,
                  dealii::ExcMessage(
                    "Parameter <Scene/Cylinder over block/Block "
                    "subdivisions> needs two values: horizontal, vertical."));
      prm.leave_subsection();
    }



    void
    CylinderCompression::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Cylinder compression");
      prm.declare_entry("Radius", "6.35", Patterns::Double(), "");
      prm.declare_entry("Height",
                        "12.7",
                        Patterns::Double(),
                        "Full height; the model holds the upper half.");
      prm.declare_entry("Radial refinements",
                        "2",
                        Patterns::Integer(0, 8),
                        "Refinements of the quarter-disc cross section.");
      prm.declare_entry("Axial cells",
                        "4",
                        Patterns::Integer(1),
                        "Cells over the half height before refinement "
                        "(structured mesh only).");
      prm.declare_entry(
        "Mesh",
        "structured",
        Patterns::Selection("structured|split corner"),
        "structured: the meridian section is a grid (2D: 2^r x axial "
        "cells; 3D: quarter disc extruded), and the rim corner (top face "
        "meets lateral face) is the corner of one cell, which goes flat "
        "when the side folds onto the plate. split corner: the meridian "
        "section is three blocks, each refined r times, two of which meet "
        "at the rim corner along its bisector, so a fold opens each of "
        "them to about 90 degrees; in 3D the outer 3/4 of the radius is "
        "this section swept around the axis, the inner 1/4 a quarter disc "
        "extruded (Axial cells unused).");
      prm.declare_entry("Imperfection",
                        "0",
                        Patterns::Double(0, 0.5),
                        "Relative reduction of the radius at the mid plane "
                        "z = 0, decreasing linearly to 0 at z = h/2 (the "
                        "necking bar's trigger: 0.018).");
      prm.leave_subsection();
    }



    void
    CylinderCompression::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Cylinder compression");
      radius             = positive(prm, "Radius");
      height             = positive(prm, "Height");
      radial_refinements = prm.get_integer("Radial refinements");
      axial_cells        = prm.get_integer("Axial cells");
      split_corner       = (prm.get("Mesh") == "split corner");
      imperfection       = prm.get_double("Imperfection");
      prm.leave_subsection();
    }



    void
    RingOnFoundation::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Ring on foundation");
      prm.declare_entry("Inner radius", "90", Patterns::Double(), "");
      prm.declare_entry("Interface radius",
                        "95",
                        Patterns::Double(),
                        "Radius between the inner (body 0) and the outer "
                        "(body 1) layer.");
      prm.declare_entry("Outer radius", "100", Patterns::Double(), "");
      prm.declare_entry("Circumferential cells",
                        "64",
                        Patterns::Integer(2),
                        "Cells along the half circumference.");
      prm.declare_entry("Radial cells per layer", "1", Patterns::Integer(1));
      prm.declare_entry("Foundation width", "260", Patterns::Double(), "");
      prm.declare_entry("Foundation height", "50", Patterns::Double(), "");
      prm.declare_entry("Foundation cells",
                        "52, 10",
                        Patterns::Anything(),
                        "Cells in x and y of the foundation.");
      prm.declare_entry("Gap",
                        "20",
                        Patterns::Double(0),
                        "Distance between the ring's bottom and the "
                        "foundation's top (y = 0).");
      prm.declare_entry("Whole ring",
                        "false",
                        Patterns::Bool(),
                        "false: the lower half ring of the paper (its ends, "
                        "the cut at the centre height, are boundaries 2 and "
                        "3); true: the whole ring, 2 x Circumferential cells "
                        "around (no ends), e.g. for a ring dropped in "
                        "dynamics.");
      prm.leave_subsection();
    }



    void
    RingOnFoundation::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Ring on foundation");
      inner_radius           = positive(prm, "Inner radius");
      interface_radius       = positive(prm, "Interface radius");
      outer_radius           = positive(prm, "Outer radius");
      circumferential_cells  = prm.get_integer("Circumferential cells");
      radial_cells_per_layer = prm.get_integer("Radial cells per layer");
      foundation_width       = positive(prm, "Foundation width");
      foundation_height      = positive(prm, "Foundation height");
      foundation_cells       = cell_counts(prm, "Foundation cells");
      gap                    = prm.get_double("Gap");
      whole_ring             = prm.get_bool("Whole ring");
      AssertThrow(inner_radius < interface_radius &&
                    interface_radius < outer_radius,
                  dealii::ExcMessage(
                    "Scene/Ring on foundation: need Inner radius < Interface "
                    "radius < Outer radius."));
      AssertThrow(foundation_cells.size() == 2,
                  dealii::ExcMessage("Parameter <Scene/Ring on foundation/"
                                     "Foundation cells> needs two values."));
      prm.leave_subsection();
    }



    void
    Scene::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Scene");
      // The scenes that registered themselves (source/scene/).
      std::string names;
      for (const auto &name : scene_names())
        names += (names.empty() ? "" : "|") + name;
      prm.declare_entry(
        "Name",
        "block",
        Patterns::Selection(names),
        "The geometry generator. Body (material) and boundary ids of each "
        "are listed in the README.");
      prm.declare_entry("Refinement",
                        "0",
                        Patterns::Integer(0, 10),
                        "Each level doubles every cell count of the scene.");
      prm.declare_entry("Mesh file",
                        "",
                        Patterns::Anything(),
                        "Gmsh .msh file for Name = gmsh: physical tags of "
                        "cells become body ids, of faces boundary ids.");
      Block::declare_parameters(prm);
      TwoBlocks::declare_parameters(prm);
      CylinderOverBlock::declare_parameters(prm);
      CylinderCompression::declare_parameters(prm);
      RingOnFoundation::declare_parameters(prm);
      prm.leave_subsection();
    }



    void
    Scene::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Scene");
      name       = prm.get("Name");
      refinement = prm.get_integer("Refinement");
      mesh_file  = prm.get("Mesh file");
      block.parse_parameters(prm);
      two_blocks.parse_parameters(prm);
      cylinder_over_block.parse_parameters(prm);
      cylinder_compression.parse_parameters(prm);
      ring_on_foundation.parse_parameters(prm);
      prm.leave_subsection();
    }
  } // namespace Parameters
} // namespace tribos
