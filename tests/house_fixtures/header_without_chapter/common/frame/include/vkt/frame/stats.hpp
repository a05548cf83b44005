#pragma once
// Summaries of frame times for --benchmark (no lesson named: the house check
// must reject this header).
