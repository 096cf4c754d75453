#include <tribos/base/text.h>
#include <tribos/parameters/adaptivity.h>

#include <string>

namespace tribos
{
  namespace Parameters
  {
    void
    Adaptivity::declare_parameters(dealii::ParameterHandler &prm)
    {
      prm.enter_subsection("Adaptivity");
      prm.declare_entry(
        "Enable",
        "false",
        dealii::Patterns::Bool(),
        "Refine the mesh where the error indicator is large and coarsen it "
        "where it has become small, during the run. The mesh is then a "
        "p4est mesh (also in serial) whose coarse cells are the scene's "
        "cells: start from a coarse uniform scene (no local refinement), "
        "quadrilaterals or hexahedra. Quasi-static runs; in 3D against "
        "rigid masters.");
      prm.declare_entry(
        "Initial cycles",
        "4",
        dealii::Patterns::Integer(0, 20),
        "The first increment is solved, the mesh adapted to its solution's "
        "indicator and the increment solved again from the start on the new "
        "mesh, this many times (the first cycle that flags no cell ends "
        "them); from a coarse mesh, about Maximum level times.");
      prm.declare_entry(
        "Every",
        "1",
        dealii::Patterns::Integer(0),
        "Adapt the mesh at the end of every this many steps (after "
        "the step's output, so that the VTU shows the indicator that "
        "decided); 0: only the initial cycles.");
      prm.declare_entry("Strategy",
                        "fixed fraction",
                        dealii::Patterns::Selection(
                          "fixed fraction|fixed number"),
                        "fixed fraction: refine the cells with the largest "
                        "indicators that together carry Refine fraction of "
                        "its sum, coarsen those that carry the smallest "
                        "Coarsen fraction. fixed number: refine and coarsen "
                        "those fractions of the cells.");
      prm.declare_entry("Refine fraction",
                        "0.3",
                        dealii::Patterns::Double(0, 1),
                        "See Strategy (0 to 1).");
      prm.declare_entry("Coarsen fraction",
                        "0.02",
                        dealii::Patterns::Double(0, 1),
                        "See Strategy (0 to 1; with Refine fraction at most "
                        "1).");
      prm.declare_entry("Maximum level",
                        "4",
                        dealii::Patterns::Integer(0, 20),
                        "No cell is refined more than this many times from "
                        "the scene's mesh.");
      prm.declare_entry("Minimum level",
                        "0",
                        dealii::Patterns::Integer(0, 20),
                        "Coarsening stops at this many refinements of the "
                        "scene's mesh.");
      prm.declare_entry("Maximum dofs",
                        "0",
                        dealii::Patterns::Integer(0),
                        "A refinement that would exceed this many dofs "
                        "(estimated on the safe side before it is made) is "
                        "cut to the cells with the largest indicators that "
                        "fit; 0: no limit of its own. Every refinement is "
                        "also cut to as many cells as the memory of the run "
                        "holds (its machines', or the address space left "
                        "under a ulimit -v), by the estimate that refuses a "
                        "Scene/Refinement, with a warning.");
      prm.declare_entry("Bulk indicator",
                        "kelly",
                        dealii::Patterns::Selection("kelly|none"),
                        "kelly: the jump of the displacement gradient across "
                        "the cells' faces (KellyErrorEstimator), times each "
                        "body's Young's modulus so that bodies compare in "
                        "stress. none: the contact indicator alone.");
      prm.declare_entry(
        "Contact indicator weight",
        "0.5",
        dealii::Patterns::Double(0, 1),
        "The share a of the contact indicator in eta = (1 - a) eta_bulk + a "
        "eta_contact, each scaled to a largest value of 1. The contact "
        "indicator of a slave face's cell (and of the master face's cell "
        "opposite) is the jump of the pressure along the face over the "
        "largest pressure, plus 1 where the face has open and closed nodes "
        "(the edge of the contact zone), plus 1 where an open node is "
        "about to close (Closing gap factor).");
      prm.declare_entry("Closing gap factor",
                        "1",
                        Text::non_negative_number(),
                        "An open slave node whose gap is below this many "
                        "sizes of its face is about to close: its faces' "
                        "cells are marked by the contact indicator.");
      prm.declare_entry(
        "Redo on contact growth",
        "true",
        dealii::Patterns::Bool(),
        "When an increment closes slave nodes on cells below Maximum level "
        "(the contact zone grew beyond the refined cells between two "
        "adaptations), the mesh is adapted to the increment's solution at "
        "once and the increment solved again from its start on the new "
        "mesh (once per increment).");
      prm.declare_entry(
        "Contact zone depth",
        "0.25",
        Text::non_negative_number(),
        "The cells whose centres lie within this many widths of a pair's "
        "contact zone (the box of its closed slave nodes, reference "
        "configuration) are refined to the finest level the marking gives "
        "a cell of the zone, and none of them coarsened; the master faces "
        "the zone touches are refined until they are no larger than 1.5 "
        "times its finest slave face. A smooth pressure (Hertz) needs the "
        "stress under the zone as fine as the surface: slave segments of "
        "several sizes inside the zone, fine surface cells on coarse ones, "
        "or a master coarser than its slave make node-to-segment pressures "
        "oscillate. 0: off (the indicator alone decides).");
      prm.leave_subsection();
    }



    void
    Adaptivity::parse_parameters(dealii::ParameterHandler &prm)
    {
      prm.enter_subsection("Adaptivity");
      enable                 = prm.get_bool("Enable");
      initial_cycles         = prm.get_integer("Initial cycles");
      every                  = prm.get_integer("Every");
      strategy               = prm.get("Strategy") == "fixed number" ?
                                 Strategy::fixed_number :
                                 Strategy::fixed_fraction;
      refine_fraction        = prm.get_double("Refine fraction");
      coarsen_fraction       = prm.get_double("Coarsen fraction");
      maximum_level          = prm.get_integer("Maximum level");
      minimum_level          = prm.get_integer("Minimum level");
      maximum_dofs           = prm.get_integer("Maximum dofs");
      kelly                  = prm.get("Bulk indicator") == "kelly";
      contact_weight         = prm.get_double("Contact indicator weight");
      closing_gap_factor     = prm.get_double("Closing gap factor");
      redo_on_contact_growth = prm.get_bool("Redo on contact growth");
      contact_zone_depth     = prm.get_double("Contact zone depth");
      AssertThrow(refine_fraction + coarsen_fraction <= 1,
                  dealii::ExcMessage(
                    "Parameters <Adaptivity/Refine fraction> = " +
                    prm.get("Refine fraction") +
                    " and <Adaptivity/Coarsen fraction> = " +
                    prm.get("Coarsen fraction") +
                    ": together at most 1 (a cell is refined or coarsened, "
                    "not both)."));
      AssertThrow(minimum_level <= maximum_level,
                  dealii::ExcMessage("Parameter <Adaptivity/Minimum level> = " +
                                     prm.get("Minimum level") +
                                     ": at most <Adaptivity/Maximum level> = " +
                                     prm.get("Maximum level") + "."));
      AssertThrow(kelly || contact_weight > 0,
                  dealii::ExcMessage(
                    "Parameter <Adaptivity/Contact indicator weight> = " +
                    prm.get("Contact indicator weight") +
                    " with <Adaptivity/Bulk indicator> = none leaves no "
                    "indicator: a weight above 0, or kelly."));
      prm.leave_subsection();
    }
  } // namespace Parameters
} // namespace tribos
