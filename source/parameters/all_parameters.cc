#include <tribos/base/text.h>
#include <tribos/parameters/all_parameters.h>
#include <tribos/scene/scene.h>

#include <algorithm>
#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace tribos
{
  namespace Parameters
  {
    void
    AllParameters::declare_parameters(dealii::ParameterHandler &prm)
    {
      prm.declare_entry("Dimension",
                        "2",
                        dealii::Patterns::Integer(2, 3),
                        "Space dimension: 2 (plane strain) or 3.");
      Scene::declare_parameters(prm);
      FiniteElement::declare_parameters(prm);
      Materials::declare_parameters(prm);
      BoundaryConditions::declare_parameters(prm);
      Contact::declare_parameters(prm);
      NonlinearSolver::declare_parameters(prm);
      TimeStepping::declare_parameters(prm);
      LinearSolver::declare_parameters(prm);
      Output::declare_parameters(prm);
      Parallel::declare_parameters(prm);
      Verification::declare_parameters(prm);
      Adaptivity::declare_parameters(prm);
    }



    namespace
    {
      /** The entries of @p tree (a handler's JSON description, or one of
       * its subsections at @p path) into @p entries. */
      void
      collect_entries(const boost::property_tree::ptree           &tree,
                      const std::string                           &path,
                      std::map<std::string, AllParameters::Entry> &entries)
      {
        for (const auto &[name, node] : tree)
          if (node.get_child_optional("value"))
            entries[path + name] = {node.get<std::string>("value"),
                                    node.get<std::string>("default_value")};
          else
            collect_entries(node, path + name + "/", entries);
      }
    } // namespace



    void
    AllParameters::parse_parameters(dealii::ParameterHandler &prm)
    {
      {
        std::stringstream json;
        prm.print_parameters(json, dealii::ParameterHandler::JSON);
        boost::property_tree::ptree tree;
        boost::property_tree::read_json(json, tree);
        entries.clear();
        collect_entries(tree, "", entries);
      }
      dimension = prm.get_integer("Dimension");
      scene.parse_parameters(prm);
      finite_element.parse_parameters(prm);
      finite_element.resolve_degree(
        finite_element.degree == 0 ? scene.geometry->mesh_order(dimension) : 1);
      AssertThrow(!finite_element.axisymmetric || dimension == 2,
                  dealii::ExcMessage("Parameter <Finite element/Axisymmetric> "
                                     "= true needs Dimension = 2, not " +
                                     std::to_string(dimension) + "."));
      materials.parse_parameters(prm);
      boundary_conditions.parse_parameters(prm);
      boundary_conditions.check(dimension);
      contact.parse_parameters(prm);
      contact.check(dimension);
      AssertThrow(contact.smoothing !=
                      Parameters::MasterSmoothing::averaged_normals ||
                    finite_element.degree == 1,
                  dealii::ExcMessage(
                    "Parameter <Contact/Master smoothing> = <averaged "
                    "normals> is available with Finite element/Polynomial "
                    "degree = 1 only (Q2's mortar segments are curved and "
                    "carry their own normals); allowed with degree 2: "
                    "none."));
      contact.resolve_pairs(dimension, finite_element.degree);
      nonlinear_solver.parse_parameters(prm);
      time_stepping.parse_parameters(prm);
      time_stepping.check(dimension);
      if (time_stepping.dynamic())
        for (const double rho : materials.densities)
          AssertThrow(rho > 0,
                      dealii::ExcMessage("Parameter <Materials/Density> = <" +
                                         [&]()
                                         {
                                           prm.enter_subsection("Materials");
                                           const std::string value =
                                             prm.get("Density");
                                           prm.leave_subsection();
                                           return value;
                                         }() +
                                         ">: Time stepping/Integrator = <" +
                                         (time_stepping.integrator ==
                                              Parameters::Integrator::newmark ?
                                            std::string("newmark") :
                                            std::string("generalized alpha")) +
                                         "> needs every density > 0."));
      linear_solver.parse_parameters(prm);
      output.parse_parameters(prm);
      parallel.parse_parameters(prm);
      verification.parse_parameters(prm);
      AssertThrow(verification.exact_displacement.empty() ||
                    verification.exact_displacement.size() == dimension,
                  dealii::ExcMessage(
                    "Parameter <Verification/Exact displacement> needs " +
                    std::to_string(dimension) + " expressions or none."));
      adaptivity.parse_parameters(prm);
      if (adaptivity.enable)
        check_adaptivity();
      contact.carry_hanging_nodes = adaptivity.enable;
    }



    void
    AllParameters::check_adaptivity() const
    {
      // What an adaptive run does not carry over a change of the mesh yet
      // is refused, not lost.
      const auto refuse = [](const bool ok, const std::string &what)
      {
        AssertThrow(ok,
                    dealii::ExcMessage(
                      "Parameter <Adaptivity/Enable> = true: " + what));
      };
      refuse(!time_stepping.dynamic(),
             "quasi-static runs only (the velocity and acceleration are not "
             "carried over a change of the mesh); set Time stepping/"
             "Integrator = static.");
      refuse(parallel.mesh == Parallel::Mesh::distributed,
             "the mesh is a p4est mesh, distributed; Parallel/Mesh = shared "
             "is not allowed.");
      refuse(parallel.rebalance_threshold == 0,
             "an adaptation partitions the mesh again itself; Parallel/"
             "Rebalance threshold must be 0.");
      refuse(!finite_element.split_into_simplices,
             "deal.II 9.4 has no hanging nodes on triangles and tetrahedra; "
             "Finite element/Cells must be as meshed, on quadrilaterals or "
             "hexahedra.");
    }



    namespace
    {
      /** Print one subsection tree of the JSON description as .prm. */
      void
      print_tree(const boost::property_tree::ptree &tree,
                 std::ostream                      &out,
                 const unsigned int                 indent)
      {
        const std::string pad(indent, ' ');
        // Entries first, then subsections, as in deal.II's own output.
        for (const auto &[name, node] : tree)
          if (node.get_child_optional("value"))
          {
            // Word-wrap the documentation to 78 columns.
            std::istringstream words(node.get<std::string>("documentation"));
            std::string        line;
            for (std::string word; words >> word;)
            {
              if (!line.empty() &&
                  pad.size() + 2 + line.size() + 1 + word.size() > 78)
              {
                out << pad << "# " << line << '\n';
                line.clear();
              }
              line += (line.empty() ? "" : " ") + word;
            }
            if (!line.empty())
              out << pad << "# " << line << '\n';
            out << pad << "# Default: <"
                << node.get<std::string>("default_value") << ">  Allowed: "
                << node.get<std::string>("pattern_description") << '\n'
                << pad << "set " << name << " = "
                << node.get<std::string>("value") << "\n\n";
          }
        for (const auto &[name, node] : tree)
          if (!node.get_child_optional("value"))
          {
            out << pad << "subsection " << name << "\n\n";
            print_tree(node, out, indent + 2);
            out << pad << "end\n\n";
          }
      }
    } // namespace



    void
    print_documented_parameters(dealii::ParameterHandler &prm,
                                std::ostream             &out)
    {
      std::stringstream json;
      prm.print_parameters(json, dealii::ParameterHandler::JSON);
      boost::property_tree::ptree tree;
      boost::property_tree::read_json(json, tree);
      out << "# tribos: every parameter with its documentation, default and "
             "allowed values.\n\n";
      print_tree(tree, out, 0);
    }



    void
    apply_overrides(dealii::ParameterHandler       &prm,
                    const std::vector<std::string> &overrides)
    {
      for (const auto &assignment : overrides)
      {
        const auto equal = assignment.find('=');
        AssertThrow(equal != std::string::npos,
                    dealii::ExcMessage("--set <" + assignment +
                                       ">: expected 'Section/Entry=value'."));
        const std::string path  = assignment.substr(0, equal);
        const std::string value = assignment.substr(equal + 1);

        std::vector<std::string> sections;
        std::string::size_type   begin = 0, slash;
        while ((slash = path.find('/', begin)) != std::string::npos)
        {
          sections.push_back(path.substr(begin, slash - begin));
          begin = slash + 1;
        }
        const std::string entry = path.substr(begin);

        unsigned int n_entered = 0;
        try
        {
          for (const auto &section : sections)
          {
            prm.enter_subsection(section);
            ++n_entered;
          }
          prm.set(entry, value);
        }
        catch (const dealii::ExceptionBase &error)
        {
          // Which of the two: an entry that does not exist, or a value its
          // pattern refuses (the pattern says what it allows).
          const bool declared =
            n_entered == sections.size() &&
            dynamic_cast<const dealii::ParameterHandler::ExcEntryUndeclared *>(
              &error) == nullptr;
          for (; n_entered > 0; --n_entered)
            prm.leave_subsection();
          const std::string shown = "--set <" + Text::abbreviate(path) + "=" +
                                    Text::abbreviate(value) + ">: ";
          AssertThrow(declared,
                      dealii::ExcMessage(
                        shown + "<" + Text::abbreviate(path) +
                        "> is not a declared parameter. Run 'tribos "
                        "--print-parameters' for every entry and its "
                        "allowed values."));
          std::ostringstream reason;
          error.print_info(reason);
          std::string why = reason.str();
          std::replace(why.begin(), why.end(), '\n', ' ');
          AssertThrow(false,
                      dealii::ExcMessage(
                        shown + "<" + Text::abbreviate(value) +
                        "> is not an allowed value of <" + path +
                        ">: " + Text::abbreviate(Text::trim(why), 400)));
        }
        for (; n_entered > 0; --n_entered)
          prm.leave_subsection();
      }
    }



    void
    read_input(dealii::ParameterHandler       &prm,
               const std::string              &filename,
               const std::vector<std::string> &overrides)
    {
      if (!filename.empty())
      {
        AssertThrow(std::filesystem::is_regular_file(filename),
                    dealii::ExcMessage("Parameter file <" + filename +
                                       "> does not exist or is not a "
                                       "regular file."));
        prm.parse_input(filename);
      }
      apply_overrides(prm, overrides);
      // A relative Scene/Mesh file (or Input deck) that is not beside the
      // working directory is looked for beside the parameter file (the
      // scenes of parameters/ name their meshes so, and run from anywhere).
      if (!filename.empty())
      {
        prm.enter_subsection("Scene");
        for (const char *entry : {"Mesh file", "Input deck"})
        {
          const std::filesystem::path mesh = prm.get(entry);
          const std::filesystem::path beside =
            std::filesystem::path(filename).parent_path() / mesh;
          if (!mesh.empty() && mesh.is_relative() &&
              !std::filesystem::exists(mesh) &&
              std::filesystem::is_regular_file(beside))
            prm.set(entry, beside.string());
        }
        prm.leave_subsection();
      }
    }



    std::vector<std::string>
    input_file_warnings(const std::string &filename)
    {
      std::ifstream in(filename);
      for (std::string line; std::getline(in, line);)
      {
        const auto first = line.find_first_not_of(" \t");
        if (first != std::string::npos && line.compare(first, 4, "set ") == 0)
          return {};
      }
      return {"parameter file <" + filename +
              "> sets no entry: every parameter has its default "
              "(tribos --print-parameters lists them)."};
    }



    unsigned int
    read_dimension(const std::string              &filename,
                   const std::vector<std::string> &overrides)
    {
      dealii::ParameterHandler prm;
      prm.declare_entry("Dimension", "2", dealii::Patterns::Integer(2, 3));
      if (!filename.empty())
      {
        AssertThrow(std::filesystem::is_regular_file(filename),
                    dealii::ExcMessage("Parameter file <" + filename +
                                       "> does not exist or is not a "
                                       "regular file."));
        prm.parse_input(filename, "", /*skip_undefined=*/true);
      }
      std::vector<std::string> dimension_overrides;
      for (const auto &o : overrides)
        if (o.rfind("Dimension=", 0) == 0)
          dimension_overrides.push_back(o);
      apply_overrides(prm, dimension_overrides);
      return prm.get_integer("Dimension");
    }
  } // namespace Parameters
} // namespace tribos
