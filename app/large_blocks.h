// How the tsf program allocates large blocks: on transparent huge pages,
// and freed memory kept for reuse (app/large_blocks.cpp says why).
#pragma once

namespace tsf::cli {

/// The allocator's settings for the program; main calls it before anything
/// else allocates. The libraries never call it.
void setUpLargeBlocks();

}  // namespace tsf::cli
