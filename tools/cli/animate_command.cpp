// koppel animate: the mechanism moving through one cycle as an animated GIF (tools/export, gif.hpp).
#include "commands.hpp"
#include "common.hpp"
#include "cycle_flags.hpp"
#include "model_loading.hpp"

#include "koppel/export/export.hpp"

#include <charconv>
#include <cmath>
#include <tuple>

namespace koppel::cli {
namespace animate_command {  // this file's own names, apart from the other commands' in a unity build
namespace {

struct Args {
  std::string file, frames = "72", size = "640x480", fps = "24", out;
  std::vector<std::string> sets;
  CycleFlags cycle;
};

// "WxH" in px; Exit{2} for anything else.
std::pair<int, int> ParseSize(const std::string& text) {
  const size_t x = text.find('x');
  int width = 0, height = 0;
  auto whole = [](const std::string& part, int& value) {
    const auto [end, error] = std::from_chars(part.data(), part.data() + part.size(), value);
    return !part.empty() && error == std::errc() && end == part.data() + part.size();
  };
  if (x == std::string::npos || !whole(text.substr(0, x), width) || !whole(text.substr(x + 1), height)) {
    Complain("--size: expected WIDTHxHEIGHT in px, such as 640x480 (got '" + text + "')");
    throw Exit{kExitBadInput};
  }
  return {width, height};
}

void Run(const Args& args) {
  const Model model = LoadModel(args.file, args.sets);
  plot::AnimationOptions options;
  options.cycle = ReadCycleFlags(model, args.cycle);
  const double frames = ParseNumberFlag("--frames", args.frames);
  options.frames = frames >= 0 && frames <= kMaxAnimationFrames && frames == std::floor(frames) ? static_cast<int>(frames) : -1;
  plot::GifOptions gif;
  std::tie(gif.width, gif.height) = ParseSize(args.size);
  gif.fps = ParseNumberFlag("--fps", args.fps);
  std::string why;
  if (!options.IsValid(&why)) {
    Complain("--frames: " + why + " (got " + args.frames + ")");
    throw Exit{kExitBadInput};
  }
  if (!gif.IsValid(options.frames, &why)) {
    Complain("--size/--fps/--frames: " + why);
    throw Exit{kExitBadInput};
  }
  WriteExportResult(args.file, args.out, plot::AnimateGif(model.mechanism(), options, gif));
}

}  // namespace
}  // namespace animate_command

void AddAnimateCommand(CLI::App& app) {
  using namespace animate_command;
  auto args = std::make_shared<Args>();
  CLI::App* cmd = app.add_subcommand(
      "animate",
      "The mechanism moving through one cycle as an animated GIF (drawn with cairo, encoded with giflib; loops forever):\n"
      "a full turn of the drive, or its drivable range there and back (limit to limit), on the assembly branch. The\n"
      "links are drawn as the plates of `koppel export --dxf` with their holes and slots, the frame's pivots with the\n"
      "ground symbol, the traced coupler curves as they grow, the input in the caption; one view fits every frame.\n"
      "--fps sets the frame rate; a GIF counts delays in 1/100 s, so the delay is round(100/fps) (24 fps plays at 25).\n"
      "Example: koppel animate catalog/entries/mzc-crank-rocker.yaml --frames 36 -o m.gif");
  cmd->add_option("file", args->file, "Mechanism YAML file")->required();
  cmd->add_option("--frames", args->frames, "Frames per cycle, 1 .. 3600 (default 72)");
  cmd->add_option("--size", args->size, "Picture size WIDTHxHEIGHT [px], each 16 .. 4096 (default 640x480)");
  cmd->add_option("--fps", args->fps, "Frames per second, 0.1 .. 50 (default 24)");
  AddCycleFlags(cmd, args->cycle);
  cmd->add_option("--set", args->sets, "Override a parameter: NAME=VALUE");
  OutputFile(cmd->add_option("-o,--output-file", args->out, "Write the GIF to this file instead of stdout"));
  cmd->callback([args] { Run(*args); });
}

}  // namespace koppel::cli
