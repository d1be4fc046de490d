#include "support/run.hpp"

#include "support/temp_file.hpp"

#include <cstdlib>
#include <sys/wait.h>

namespace koppel::test {

RunResult RunKoppel(const std::string& arguments) {
  TempDir dir;
  const std::string out = (dir.path() / "out").string(), err = (dir.path() / "err").string();
  const std::string command = std::string(KOPPEL_EXECUTABLE) + " " + arguments + " > " + out + " 2> " + err + " < /dev/null";
  const int status = std::system(command.c_str());
  RunResult r;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = ReadText(out);
  r.err = ReadText(err);
  return r;
}

}  // namespace koppel::test
