#include "graspsim/io/shell_quote.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <string>

namespace {

// Oracle: /bin/sh itself. printf '%s' WORD prints the word the shell parsed, which must be the
// original text, whatever quotes, spaces and shell characters it holds.
std::string echoThroughShell(const std::string& word) {
    FILE* pipe = popen(("printf '%s' " + word).c_str(), "r");
    std::string out;
    char buffer[256];
    std::size_t n = 0;
    while ((n = fread(buffer, 1, sizeof buffer, pipe)) > 0) out.append(buffer, n);
    pclose(pipe);
    return out;
}

TEST(ShellQuote, TheShellGetsBackTheTextUnchanged) {
    for (const std::string text : {"plain", "with space", "it's", "'", "''a'b''", "$HOME `ls` \"x\" \\n; rm -rf /tmp/nothing", ""}) {
        EXPECT_EQ(echoThroughShell(graspsim::io::quoteForShell(text)), text) << text;
    }
}

}  // namespace
