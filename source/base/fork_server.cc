#include <tribos/base/fork_server.h>

#include <fcntl.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <string>

namespace tribos
{
  namespace
  {
    /**
     * One line of standard input, read a byte at a time with read(2): no
     * stream buffer that a child would inherit half-read. False at the
     * end of the input.
     */
    bool
    read_line(std::string &line)
    {
      line.clear();
      char c;
      for (;;)
      {
        const ssize_t n = read(STDIN_FILENO, &c, 1);
        if (n < 0 && errno == EINTR)
          continue;
        if (n <= 0)
          return !line.empty();
        if (c == '\n')
          return true;
        line.push_back(c);
      }
    }



    /** Write @p text to standard output whole (the answer to a request). */
    void
    answer(const std::string &text)
    {
      std::size_t written = 0;
      while (written < text.size())
      {
        const ssize_t n =
          write(STDOUT_FILENO, text.data() + written, text.size() - written);
        if (n < 0 && errno == EINTR)
          continue;
        if (n <= 0)
          std::_Exit(1);
        written += n;
      }
    }



    /** Open @p file as the descriptor @p target (false if it cannot). */
    bool
    redirect(const std::string &file, const int flags, const int target)
    {
      const int descriptor = open(file.c_str(), flags, 0644);
      if (descriptor < 0)
        return false;
      if (descriptor != target)
      {
        if (dup2(descriptor, target) < 0)
          return false;
        close(descriptor);
      }
      return true;
    }
  } // namespace



  std::optional<std::vector<char *>>
  ForkServer::serve(const char *program_name)
  {
    // What the child keeps: its arguments, for the rest of the process.
    static std::vector<std::string> arguments;
    static std::vector<char *>      pointers;

    std::string line;
    while (read_line(line))
    {
      if (line.rfind("run ", 0) != 0)
      {
        answer("error request <" + line + "> is not \"run N\"\n");
        continue;
      }
      const unsigned long n_arguments = std::strtoul(line.c_str() + 4, 0, 10);
      std::string         directory, out, err;
      read_line(directory);
      read_line(out);
      read_line(err);
      read_line(line);
      const unsigned long      n_variables = std::strtoul(line.c_str(), 0, 10);
      std::vector<std::string> environment(n_variables);
      for (auto &variable : environment)
        read_line(variable);
      arguments.assign(1, program_name);
      for (unsigned long i = 0; i < n_arguments; ++i)
      {
        read_line(line);
        arguments.push_back(line);
      }

      const pid_t child = fork();
      if (child < 0)
      {
        answer("error fork failed\n");
        continue;
      }
      if (child == 0)
      {
        // (The directory first: relative output files are in it.)
        if (chdir(directory.c_str()) != 0 ||
            !redirect("/dev/null", O_RDONLY, STDIN_FILENO) ||
            !redirect(out, O_WRONLY | O_CREAT | O_TRUNC, STDOUT_FILENO) ||
            !redirect(err, O_WRONLY | O_CREAT | O_TRUNC, STDERR_FILENO))
          std::_Exit(127);
        clearenv();
        for (const auto &variable : environment)
        {
          const auto equal = variable.find('=');
          if (equal != std::string::npos && equal > 0)
            setenv(variable.substr(0, equal).c_str(),
                   variable.c_str() + equal + 1,
                   1);
        }
        for (auto &argument : arguments)
          pointers.push_back(argument.data());
        pointers.push_back(nullptr);
        return pointers;
      }

      int status = 0;
      while (waitpid(child, &status, 0) < 0 && errno == EINTR)
        ;
      if (WIFSIGNALED(status))
        answer("signal " + std::to_string(WTERMSIG(status)) + "\n");
      else
        answer("exit " + std::to_string(WEXITSTATUS(status)) + "\n");
    }
    return std::nullopt;
  }
} // namespace tribos
