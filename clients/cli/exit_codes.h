// Exit codes of the contract (§1), shared by all commands.
#pragma once

namespace radiant::cli {

constexpr int kExitOk = 0;
constexpr int kExitFailure = 1;   ///< internal failure; a message is on stderr
constexpr int kExitBadInput = 2;  ///< bad input; nothing was written

}  // namespace radiant::cli
