/*
 * Checkpoints and restarts, the part that says what the state belongs to:
 * the fingerprint of the parameters (every entry but those a restart may
 * change) and the entries in which a restart differs from it.
 */

#include <tribos/base/text.h>
#include <tribos/core/checkpointer.h>
#include <tribos/material/material_model.h>

#include <cmath>
#include <cstdlib>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace tribos
{
  namespace
  {
    /**
     * The entries a restart may change (Checkpointer::may_change_at_restart();
     * "Section/": all of its entries). Time stepping's entries here size the
     * increments; its integrator's (Integrator, Newmark beta, ..., Initial
     * velocity) define the model and are compared.
     */
    constexpr const char *may_change[] = {
      "Time stepping/End time",
      "Time stepping/Number of steps",
      "Time stepping/Maximum cutbacks",
      "Time stepping/Growth factor",
      "Time stepping/Easy iterations",
      "Time stepping/Growth after converged increments",
      "Time stepping/Extrapolation",
      "Time stepping/Initial increment",
      "Time stepping/Minimum increment",
      "Time stepping/Maximum increment",
      "Time stepping/Output times",
      "Time stepping/Maximum contact changes",
      "Nonlinear solver/",
      "Linear solver/",
      "Parallel/",
      "Output/",
      "Verification/",
      "Scene/Mesh file",
      "Scene/Input deck"};

    /**
     * @p text as compared: blanks around the separators , ; : = ( ) and
     * repeated blanks dropped, and every item that is a number in one form
     * (0.3, 0.30 and 3e-1 alike), so that an entry written otherwise but
     * with the same meaning is the same. Expressions and names stay as
     * written.
     */
    std::string
    comparable(const std::string &text)
    {
      std::string result, item;
      const auto  flush = [&]()
      {
        std::istringstream words(item);
        std::string        word, collapsed;
        while (words >> word)
          collapsed += (collapsed.empty() ? "" : " ") + word;
        char        *end   = nullptr;
        const double value = std::strtod(collapsed.c_str(), &end);
        if (!collapsed.empty() && end == collapsed.c_str() + collapsed.size() &&
            std::isfinite(value))
        {
          std::ostringstream number;
          number.precision(17);
          number << value;
          collapsed = number.str();
        }
        result += collapsed;
        item.clear();
      };
      for (const char c : text)
        if (std::string(",;:=()").find(c) != std::string::npos)
        {
          flush();
          result += c;
        }
        else
          item += c;
      flush();
      return result;
    }

  } // namespace



  template <int dim>
  bool
  Checkpointer<dim>::may_change_at_restart(const std::string &path)
  {
    for (const char *entry : may_change)
    {
      const std::string allowed(entry);
      // "Section/" allows the whole subsection.
      if (allowed.back() == '/' ?
            path.compare(0, allowed.size(), allowed) == 0 :
            path == allowed)
        return true;
    }
    return false;
  }



  template <int dim>
  std::string
  Checkpointer<dim>::may_change_at_restart_list()
  {
    std::string list;
    for (const char *entry : may_change)
      list += (list.empty() ? "" : ", ") + std::string(entry) +
              (std::string(entry).back() == '/' ? "*" : "");
    return list;
  }



  template <int dim>
  std::map<std::string, std::string>
  Checkpointer<dim>::fingerprint() const
  {
    std::map<std::string, std::string> fingerprint;
    for (const auto &[path, entry] : parameters.entries)
      if (!may_change_at_restart(path))
        fingerprint[path] = entry.value;
    // The parsed material constants replace their entries' text (the same
    // numbers written otherwise are the same model).
    for (const auto &[name, value] : resolved_values())
      fingerprint[name] = value;
    return fingerprint;
  }



  template <int dim>
  std::map<std::string, std::string>
  Checkpointer<dim>::resolved_values() const
  {
    const auto &m    = parameters.materials;
    const auto  list = [](const auto &values)
    {
      std::ostringstream text;
      text.precision(17);
      for (unsigned int i = 0; i < values.size(); ++i)
        text << (i > 0 ? ", " : "") << values[i];
      return text.str();
    };
    std::string pairs;
    for (const auto &pair : parameters.contact.pairs)
      pairs += (pairs.empty() ? "" : " ; ") + pair.text;
    // What Contact/Penalty formulation and Master smoothing chose for
    // each pair (automatic: resolve_pairs()), so that a checkpoint of a
    // file without them meets the same choice, whatever the entry said.
    std::string formulations, smoothings;
    for (const auto &pair : parameters.contact.pairs)
    {
      formulations += (formulations.empty() ? "" : ", ") +
                      std::string(pair.penalty_formulation ==
                                      Parameters::PenaltyFormulation::mixed ?
                                    "mixed" :
                                    "primal");
      smoothings +=
        (smoothings.empty() ? "" : ", ") +
        std::string(pair.smoothing == Parameters::MasterSmoothing::none ?
                      "none" :
                      "averaged normals");
    }
    std::map<std::string, std::string> fingerprint = {
      {"Scene/Name", parameters.scene.name},
      {"Contact/Pairs", pairs},
      {"Contact/Penalty formulation", formulations},
      {"Contact/Master smoothing", smoothings},
      {"Materials/Model", list(m.models)},
      {"Materials/Young's modulus", list(m.youngs_moduli)},
      {"Materials/Poisson's ratio", list(m.poissons_ratios)}};
    // The models' own entries (J2 plasticity's Materials/Yield stress).
    for (const std::string &name : material_registry().names())
      for (const auto &[entry, values] : m.model(name)->fingerprint())
        fingerprint[entry] = list(values);
    return fingerprint;
  }



  template <int dim>
  std::vector<std::string>
  Checkpointer<dim>::changed_entries(const Checkpoint &c) const
  {
    std::vector<std::string> changed;
    for (const auto &[name, value] : fingerprint())
    {
      const auto  stored = c.fingerprint.find(name);
      std::string there;
      if (stored != c.fingerprint.end())
        there = stored->second;
      else
      {
        // An entry that the checkpoint's tribos did not have: that run
        // did what its default does.
        const auto entry = parameters.entries.find(name);
        if (entry != parameters.entries.end())
          there = entry->second.default_value;
      }
      if (comparable(there) != comparable(value))
        changed.push_back(name + " <" + Text::abbreviate(there) + "> there, <" +
                          Text::abbreviate(value) + "> here");
    }
    return changed;
  }

  template class Checkpointer<2>;
  template class Checkpointer<3>;
} // namespace tribos
