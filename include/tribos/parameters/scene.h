#ifndef tribos_parameters_scene_h
#define tribos_parameters_scene_h

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

namespace tribos
{
  namespace Parameters
  {
    /** Subsection `Scene/Block`: one body, an axis-parallel box. */
    struct Block
    {
      std::vector<double>       lower_corner;
      std::vector<double>       upper_corner;
      std::vector<unsigned int> subdivisions;

      static void
      declare_parameters(dealii::ParameterHandler &prm);
      void
      parse_parameters(dealii::ParameterHandler &prm);
    };

    /**
     * Subsection `Scene/Two blocks`: a lower and an upper box with
     * independent (non-matching) meshes, the upper one above the lower one.
     */
    struct TwoBlocks
    {
      std::vector<double>       lower_size;
      std::vector<double>       upper_size;
      std::vector<unsigned int> lower_subdivisions;
      std::vector<unsigned int> upper_subdivisions;
      double                    gap;
      double                    upper_offset;
      /** Radius of the upper block's arc-shaped bottom; 0: flat. */
      double upper_bottom_radius;
      /** Lower and upper corner of the box whose cells are refined
       * box_refinements times after the merge (empty: none). */
      std::vector<double> box_lower, box_upper;
      unsigned int        box_refinements;

      static void
      declare_parameters(dealii::ParameterHandler &prm);
      void
      parse_parameters(dealii::ParameterHandler &prm);
    };

    /**
     * Subsection `Scene/Cylinder over block`: the lower half of a cylinder
     * (2D) or a quarter of the lower hemisphere (3D) above a block: the Hertz
     * geometry.
     */
    struct CylinderOverBlock
    {
      double                    radius;
      double                    gap;
      double                    block_width;
      double                    block_height;
      std::vector<unsigned int> block_subdivisions;
      unsigned int              indenter_refinements;
      bool                      with_block;
      /** "lower half", "whole" or "meridian". */
      std::string  indenter_shape;
      unsigned int contact_refinements;
      double       refinement_radius;

      static void
      declare_parameters(dealii::ParameterHandler &prm);
      void
      parse_parameters(dealii::ParameterHandler &prm);
    };

    /**
     * Subsection `Scene/Cylinder compression`: one eighth of a cylinder
     * (3D) or a quarter of its meridian section (2D), paper section 4.1.
     */
    struct CylinderCompression
    {
      double       radius;
      double       height;
      unsigned int radial_refinements;
      unsigned int axial_cells;
      /** Meridian section of three blocks, the rim corner split. */
      bool split_corner;
      /** Relative radius reduction at the mid plane (linear taper). */
      double imperfection;

      static void
      declare_parameters(dealii::ParameterHandler &prm);
      void
      parse_parameters(dealii::ParameterHandler &prm);
    };

    /**
     * Subsection `Scene/Ring on foundation`: lower half of a two-layer ring
     * above a foundation block, paper section 4.2 (2D only).
     */
    struct RingOnFoundation
    {
      double                    inner_radius;
      double                    interface_radius;
      double                    outer_radius;
      unsigned int              circumferential_cells;
      unsigned int              radial_cells_per_layer;
      double                    foundation_width;
      double                    foundation_height;
      std::vector<unsigned int> foundation_cells;
      double                    gap;
      /** The whole ring instead of its lower half (dynamics: a ring in
       * flight). */
      bool whole_ring;

      static void
      declare_parameters(dealii::ParameterHandler &prm);
      void
      parse_parameters(dealii::ParameterHandler &prm);
    };

    /** Subsection `Scene`: which geometry to build and how fine. */
    struct Scene
    {
      std::string  name;
      unsigned int refinement;
      std::string  mesh_file;

      Block               block;
      TwoBlocks           two_blocks;
      CylinderOverBlock   cylinder_over_block;
      CylinderCompression cylinder_compression;
      RingOnFoundation    ring_on_foundation;

      static void
      declare_parameters(dealii::ParameterHandler &prm);
      void
      parse_parameters(dealii::ParameterHandler &prm);
    };
  } // namespace Parameters
} // namespace tribos

#endif
