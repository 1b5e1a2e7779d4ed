// SPDX-License-Identifier: BSD-3-Clause
/* Every input the fuzz targets found defective (tests/data/fuzz_regressions/<target>-<what>), fed to its
   reader through the same decoding as the fuzz target (tests/fuzz/FuzzTargets.h): each must be refused with
   an InputError whose message names the file (no other exception type, no crash, no huge allocation: the
   sanitizer pass, scripts/sanitize.sh, runs this test too). */
#include "fuzz/FuzzTargets.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>

namespace fs = std::filesystem;

namespace
{
    std::string readAll(const fs::path &p)
    {
        std::ifstream in(p, std::ios::binary);
        return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    }
} // namespace

TEST(FuzzRegressions, EveryKeptInputIsRefusedWithAnInputError)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_NONE);
    const fs::path dir = fs::path(MHPLAN_TEST_DATA_DIR) / "fuzz_regressions";
    ASSERT_TRUE(fs::is_directory(dir)) << dir;
    std::size_t count = 0;
    for (const auto &entry : fs::directory_iterator(dir))
    {
        const std::string name = entry.path().filename().string();
        if (name == "README.md")
            continue;
        const auto dash = name.find('-');
        ASSERT_NE(dash, std::string::npos) << "regression files are named <target>-<what>: " << name;
        const auto &targets = mhplan::fuzz::targets();
        const auto it = targets.find(name.substr(0, dash));
        ASSERT_NE(it, targets.end()) << "unknown fuzz target in " << name;
        const std::string input = readAll(entry.path());
        try
        {
            it->second(input);
            ADD_FAILURE() << name << ": accepted, expected an InputError";
        }
        catch (const mhplan::InputError &e)
        {
            // Readers name their file ("fuzz.*"); command-line values name the option or the parameter.
            if (it->first != "cli_values")
            {
                EXPECT_NE(std::string(e.what()).find("fuzz"), std::string::npos)
                    << name << ": the message names no file: " << e.what();
            }
        }
        catch (const std::exception &e)
        {
            ADD_FAILURE() << name << ": escaped as another exception: " << e.what();
        }
        ++count;
    }
    // The two findings of the first fuzzing run (issue 19) at least.
    EXPECT_GE(count, 2u);
}
