#include <tribos/base/text.h>
#include <tribos/parameters/boundary_conditions.h>

namespace tribos
{
  namespace Parameters
  {
    namespace
    {
      unsigned int
      read_boundary_id(const std::string &text, const std::string &entry)
      {
        const auto ids = Text::parse_unsigned(text, entry);
        AssertThrow(ids.size() == 1,
                    dealii::ExcMessage("Parameter <" + entry +
                                       ">: expected one boundary id, got <" +
                                       text + ">."));
        return ids[0];
      }
    } // namespace



    void
    BoundaryConditions::declare_parameters(dealii::ParameterHandler &prm)
    {
      prm.enter_subsection("Boundary conditions");
      prm.declare_entry(
        "Dirichlet",
        "",
        dealii::Patterns::Anything(),
        "Prescribed displacements: items 'id : components : values' "
        "separated by ';'. components is a subset of 'xyz'; values holds one "
        "expression in x, y, z, t per component, comma-separated. Example: "
        "'0 : xy : 0, 0 ; 3 : y : -0.1*t'.");
      prm.declare_entry("Symmetry",
                        "",
                        dealii::Patterns::Anything(),
                        "Boundary ids of symmetry planes (no normal "
                        "displacement, free tangential), comma-separated.");
      prm.declare_entry(
        "Neumann",
        "",
        dealii::Patterns::Anything(),
        "Tractions per reference area (dead loads): items 'id : tx, ty(, tz)' "
        "separated by ';', expressions in x, y, z, t.");
      prm.declare_entry("Body force",
                        "",
                        dealii::Patterns::Anything(),
                        "Force per reference volume, dim comma-separated "
                        "expressions in x, y, z, t; empty for none.");
      prm.leave_subsection();
    }



    void
    BoundaryConditions::parse_parameters(dealii::ParameterHandler &prm)
    {
      prm.enter_subsection("Boundary conditions");
      dirichlet.clear();
      neumann.clear();

      const std::string dirichlet_entry = "Boundary conditions/Dirichlet";
      for (const auto &item : Text::split_top_level(prm.get("Dirichlet"), ';'))
      {
        const auto parts = Text::split_top_level(item, ':');
        AssertThrow(parts.size() == 3,
                    dealii::ExcMessage(
                      "Parameter <" + dirichlet_entry + ">: item <" + item +
                      "> must read 'id : components : values', e.g. "
                      "'0 : xy : 0, 0'."));
        DirichletCondition condition;
        condition.boundary_id = read_boundary_id(parts[0], dirichlet_entry);
        for (const char c : parts[1])
        {
          AssertThrow(c == 'x' || c == 'y' || c == 'z',
                      dealii::ExcMessage(
                        "Parameter <" + dirichlet_entry + ">: components <" +
                        parts[1] + "> may only contain the letters x, y, z."));
          condition.components.push_back(c - 'x');
        }
        condition.expressions = Text::split_top_level(parts[2], ',');
        AssertThrow(condition.expressions.size() == condition.components.size(),
                    dealii::ExcMessage(
                      "Parameter <" + dirichlet_entry + ">: item <" + item +
                      "> names " + std::to_string(condition.components.size()) +
                      " components but gives " +
                      std::to_string(condition.expressions.size()) +
                      " values."));
        dirichlet.push_back(condition);
      }

      symmetry = Text::parse_unsigned(prm.get("Symmetry"),
                                      "Boundary conditions/Symmetry");

      for (const auto &item : Text::split_top_level(prm.get("Neumann"), ';'))
      {
        const auto parts = Text::split_top_level(item, ':');
        AssertThrow(parts.size() == 2,
                    dealii::ExcMessage(
                      "Parameter <Boundary conditions/Neumann>: item <" + item +
                      "> must read 'id : tx, ty(, tz)'."));
        NeumannCondition condition;
        condition.boundary_id =
          read_boundary_id(parts[0], "Boundary conditions/Neumann");
        condition.expressions = Text::split_top_level(parts[1], ',');
        neumann.push_back(condition);
      }

      body_force = Text::split_top_level(prm.get("Body force"), ',');
      prm.leave_subsection();
    }



    void
    BoundaryConditions::check(const unsigned int dim) const
    {
      for (unsigned int i = 0; i < dirichlet.size(); ++i)
        for (unsigned int j = 0; j < i; ++j)
          AssertThrow(dirichlet[i].boundary_id != dirichlet[j].boundary_id,
                      dealii::ExcMessage(
                        "Parameter <Boundary conditions/Dirichlet> names "
                        "boundary " +
                        std::to_string(dirichlet[i].boundary_id) +
                        " twice: give all its components in one item, e.g. "
                        "'3 : xy : 0, -t'."));
      for (unsigned int i = 0; i < neumann.size(); ++i)
        for (unsigned int j = 0; j < i; ++j)
          AssertThrow(neumann[i].boundary_id != neumann[j].boundary_id,
                      dealii::ExcMessage(
                        "Parameter <Boundary conditions/Neumann> names "
                        "boundary " +
                        std::to_string(neumann[i].boundary_id) + " twice."));
      for (const auto &condition : dirichlet)
        for (const unsigned int c : condition.components)
          AssertThrow(c < dim,
                      dealii::ExcMessage(
                        "Parameter <Boundary conditions/Dirichlet>: "
                        "component z on boundary " +
                        std::to_string(condition.boundary_id) +
                        " does not exist in 2D."));
      for (const auto &condition : neumann)
        AssertThrow(condition.expressions.size() == dim,
                    dealii::ExcMessage(
                      "Parameter <Boundary conditions/Neumann>: boundary " +
                      std::to_string(condition.boundary_id) + " needs " +
                      std::to_string(dim) + " traction components."));
      AssertThrow(body_force.empty() || body_force.size() == dim,
                  dealii::ExcMessage(
                    "Parameter <Boundary conditions/Body force> needs " +
                    std::to_string(dim) + " expressions or none."));
    }
  } // namespace Parameters
} // namespace tribos
