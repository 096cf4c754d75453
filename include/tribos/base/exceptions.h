#ifndef tribos_base_exceptions_h
#define tribos_base_exceptions_h

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

namespace tribos
{
  /**
   * Thrown when a Newton solve of one increment fails (too many iterations,
   * a diverging or non-finite residual, an inverted element). The load
   * stepper catches exactly this type to cut the increment back; every
   * other exception ends the run.
   */
  class NonConvergence : public std::runtime_error
  {
  public:
    explicit NonConvergence(const std::string &what)
      : std::runtime_error(what)
    {
    }
  };

  /** A number in scientific notation with 3 decimals, for messages. */
  inline std::string
  to_scientific(const double value)
  {
    char buffer[32];
    std::snprintf(buffer, sizeof(buffer), "%.3e", value);
    return buffer;
  }

  /** A deformation gradient with det F <= 0 was met: the iterate is void. */
  class InvertedElement : public NonConvergence
  {
  public:
    explicit InvertedElement(const std::string &what)
      : NonConvergence(what)
    {
    }

    /** The message of @p material meeting det F = @p J: "det F = -nan <=
     * 0" said nothing true about a not-a-number. */
    InvertedElement(const std::string &material, const double J)
      : NonConvergence(material + ": " +
                       (std::isfinite(J) ?
                          "det F = " + to_scientific(J) + " <= 0" :
                          std::string("det F is not finite (the iterate "
                                      "diverged)")) +
                       " at a quadrature point")
    {
    }
  };
} // namespace tribos

#endif
