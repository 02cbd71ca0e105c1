// `hypergarden keys [--markdown]`: the desktop window's keys and mouse as
// the window binds them (one table, garden/render/key_table.h), as text or
// as the README's Markdown table.
#include <iostream>

#include "cli/commands.h"
#include "garden/render/key_table.h"

namespace hg::garden::cli {

int runKeysCommand(bool markdown) {
    std::cout << (markdown ? keyTableMarkdown() : "Keys and mouse in the garden window:\n" + keyTableText());
    return 0;
}

}  // namespace hg::garden::cli
