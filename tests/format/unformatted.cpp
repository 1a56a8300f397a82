// Planted for format_check_rejects_unformatted: clang-format would change the lines below, so
// scripts/format-check must name this file. (Left out of the tree's own format check.)
int  badly_spaced( int x ){return x+1;}
