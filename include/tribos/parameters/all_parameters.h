#ifndef tribos_parameters_all_parameters_h
#define tribos_parameters_all_parameters_h

#include <tribos/parameters/adaptivity.h>
#include <tribos/parameters/boundary_conditions.h>
#include <tribos/parameters/contact.h>
#include <tribos/parameters/finite_element.h>
#include <tribos/parameters/linear_solver.h>
#include <tribos/parameters/materials.h>
#include <tribos/parameters/nonlinear_solver.h>
#include <tribos/parameters/output.h>
#include <tribos/parameters/parallel.h>
#include <tribos/parameters/scene.h>
#include <tribos/parameters/time_stepping.h>
#include <tribos/parameters/verification.h>

#include <deal.II/base/parameter_handler.h>

#include <map>
#include <ostream>
#include <string>
#include <vector>

namespace tribos
{
  namespace Parameters
  {
    /**
     * Every parameter of a run: the top-level `Dimension` plus one struct per
     * subsection. Parsing is strict: unknown entries are errors.
     */
    struct AllParameters
    {
      unsigned int dimension;

      Scene              scene;
      FiniteElement      finite_element;
      Materials          materials;
      BoundaryConditions boundary_conditions;
      Contact            contact;
      NonlinearSolver    nonlinear_solver;
      TimeStepping       time_stepping;
      LinearSolver       linear_solver;
      Output             output;
      Parallel           parallel;
      Verification       verification;
      Adaptivity         adaptivity;

      /** An entry of the ParameterHandler: its value after the file and
       * the overrides, and its default. */
      struct Entry
      {
        std::string value;
        std::string default_value;
      };
      /** Every entry the ParameterHandler declares, by its path
       * ("Section/Subsection/Entry"; a plugin's too), as parse_parameters()
       * read it: a checkpoint is compared with a restart entry by entry
       * (Checkpointer::fingerprint()), so that no entry added later is
       * forgotten there. Empty if the struct was filled by hand. */
      std::map<std::string, Entry> entries;

      /** Warnings about the input itself (e.g. a file that sets nothing),
       * reported by the run with its own. */
      std::vector<std::string> input_warnings;
      /** The checkpoint directory to go on from (--restart), or empty. */
      std::string restart_directory;

      static void
      declare_parameters(dealii::ParameterHandler &prm);
      void
      parse_parameters(dealii::ParameterHandler &prm);

    private:
      /** Refuse what an adaptive run cannot do (Adaptivity/Enable). */
      void
      check_adaptivity() const;
    };

    /**
     * Apply command-line overrides `Section/Subsection/Entry=value` to an
     * already parsed handler. An unknown entry or a value that does not match
     * the entry's pattern throws with a message that names both.
     */
    void
    apply_overrides(dealii::ParameterHandler       &prm,
                    const std::vector<std::string> &overrides);

    /**
     * Print every parameter as a loadable .prm file whose comments give the
     * documentation, default and allowed values (pattern) of each entry.
     */
    void
    print_documented_parameters(dealii::ParameterHandler &prm,
                                std::ostream             &out);

    /**
     * Read the file @p filename (if not empty) and the @p overrides into
     * @p prm, which must have all entries declared already.
     */
    void
    read_input(dealii::ParameterHandler       &prm,
               const std::string              &filename,
               const std::vector<std::string> &overrides);

    /**
     * Read only `Dimension` from the file and the overrides, ignoring every
     * other entry, so that main() can dispatch to the templated code.
     */
    /**
     * Warnings about the file @p filename itself: one that sets no entry
     * (empty, or comments only) runs every default, which is rarely meant.
     */
    std::vector<std::string>
    input_file_warnings(const std::string &filename);

    unsigned int
    read_dimension(const std::string              &filename,
                   const std::vector<std::string> &overrides);
  } // namespace Parameters
} // namespace tribos

#endif
