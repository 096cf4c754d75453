#ifndef tribos_core_vector_function_h
#define tribos_core_vector_function_h

#include <deal.II/base/function_parser.h>
#include <deal.II/base/numbers.h>
#include <deal.II/lac/vector.h>

#include <memory>
#include <string>
#include <vector>

namespace tribos
{
  using namespace dealii;

  /**
   * A FunctionParser of the "x, y(, z)" expressions in x, y, z, t of a
   * parameter @p entry (one component per expression), evaluated once so
   * that unknown symbols are reported at setup with the entry's name.
   */
  template <int dim>
  std::unique_ptr<FunctionParser<dim>>
  make_vector_function(const std::vector<std::string> &expressions,
                       const std::string              &entry)
  {
    std::string joined;
    for (unsigned int i = 0; i < expressions.size(); ++i)
      joined += (i ? ";" : "") + expressions[i];
    auto function = std::make_unique<FunctionParser<dim>>(expressions.size());
    try
    {
      function->initialize(FunctionParser<dim>::default_variable_names() + ",t",
                           joined,
                           {{"pi", numbers::PI}},
                           true);
      dealii::Vector<double> value(expressions.size());
      function->vector_value(Point<dim>(), value);
    }
    catch (...)
    {
      AssertThrow(false,
                  ExcMessage("Parameter <" + entry +
                             ">: cannot parse the expression(s) <" + joined +
                             ">. Use x, y, z, t, pi and the functions "
                             "of deal.II's FunctionParser (muparser)."));
    }
    return function;
  }
} // namespace tribos

#endif
