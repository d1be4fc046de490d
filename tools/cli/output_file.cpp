// Output files and standard output (common.hpp; the file rules themselves are
// koppel/core/output_file.hpp): the options that name outputs, claimed once the command line is
// parsed, and the writes at the end of a command.
#include "common.hpp"

#include "koppel/core/output_file.hpp"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <iostream>

namespace koppel::cli {
namespace output_file {  // this file's own names, apart from the other commands' in a unity build
namespace {

struct OutputOption {
  CLI::Option* option;
  bool directory;
};

std::vector<OutputOption>& OutputOptions() {
  static std::vector<OutputOption> options;
  return options;
}

bool stdout_failure_reported = false;

void WriteStandardOutput(const std::string& text) {
  std::cout << text;
  std::cout.flush();
  // std::cout shares stdout's buffer: a full disk or closed pipe shows in the stream or in fflush
  if (!std::cout || std::fflush(stdout) != 0 || std::ferror(stdout)) {
    const int error = errno;
    stdout_failure_reported = true;
    Complain(std::string("cannot write to standard output: ") + std::strerror(error ? error : EIO));
    throw Exit{kExitFailed};
  }
}

}  // namespace
}  // namespace output_file

CLI::Option* OutputFile(CLI::Option* option) {
  using namespace output_file;
  OutputOptions().push_back({option, false});
  return option;
}

CLI::Option* OutputDirectory(CLI::Option* option) {
  using namespace output_file;
  OutputOptions().push_back({option, true});
  return option;
}

void ClaimOutputs() {
  using namespace output_file;
  for (const OutputOption& o : OutputOptions()) {
    std::string flag = o.option->get_name(false, true);  // "-o,--output-file" -> "-o/--output-file"
    std::replace(flag.begin(), flag.end(), ',', '/');
    for (const std::string& path : o.option->results()) {
      // -o '' (an unset shell variable) names no file: it must not quietly mean standard output
      if (path.empty()) {
        Complain(flag + (o.directory ? ": the path is empty (give a directory)" : ": the path is empty (give a file name, or - for standard output)"));
        throw Exit{kExitBadInput};
      }
      if (o.directory) {
        io::ClaimOutputDirectory(path, flag);
      } else {
        io::ClaimOutputFile(path, flag);
      }
    }
  }
}

void WriteOutput(const std::string& path, const std::string& text) {
  using namespace output_file;
  if (path.empty() || path == "-") return WriteStandardOutput(text);
  io::WriteFileAtomically(path, text);
}

StreamedOutput::StreamedOutput(const std::string& path) : path_(path) {
  if (!path.empty() && path != "-") {
    file_ = std::make_unique<io::AtomicFileWriter>(path);
    text_.reserve(kPiece + kPiece / 4);  // a piece and the row that crossed its end
  }
}

StreamedOutput::~StreamedOutput() = default;

void StreamedOutput::WritePiece() {
  file_->Write(text_);
  text_.clear();
}

void StreamedOutput::Finish() {
  if (!file_) return WriteOutput(path_, text_);
  WritePiece();
  file_->Commit();
}

void MakeOutputDirectory(const std::string& path) { io::MakeOutputDirectory(path); }

int FinishStandardOutput(int code) {
  using namespace output_file;
  errno = 0;
  const bool failed = std::fflush(stdout) != 0 || std::ferror(stdout) != 0;
  const int error = errno;
  if (std::fclose(stdout) != 0 && !failed && !stdout_failure_reported) {
    Complain(std::string("cannot write to standard output: ") + std::strerror(errno ? errno : EIO));
    return code == kExitOk ? kExitFailed : code;
  }
  if (failed && !stdout_failure_reported) {
    Complain(std::string("cannot write to standard output: ") + std::strerror(error ? error : EIO));
    return code == kExitOk ? kExitFailed : code;
  }
  return code;
}

}  // namespace koppel::cli
