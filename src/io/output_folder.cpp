#include "io/output_folder.hpp"

#include <filesystem>

#include "core/error.hpp"

namespace pound {

namespace fs = std::filesystem;

std::string output_folder(const Options& opt, const std::string& input, const std::string& suffix) {
  if (opt.given("out")) return opt.get_path("out");
  const fs::path p(input);
  return (p.parent_path() / (p.stem().string() + "-" + suffix)).string();
}

void make_output_folder(const Options& opt, const std::string& dir, const std::string& input,
                        const std::vector<std::string>& names) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec || !fs::is_directory(dir))
    throw InputError(opt.where("out") + ": cannot create the folder " + dir);
  for (const auto& name : names)
    if (fs::equivalent(fs::path(dir) / name, input, ec))
      throw InputError(opt.where("out") + ": " + dir + "/" + name +
                       " is the campaign file; choose another output folder");
}

}  // namespace pound
