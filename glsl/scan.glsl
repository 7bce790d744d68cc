// Exclusive-scan block size: SCAN_WG threads x 4 elements.
const uint SCAN_WG = 256u; // export
const uint SCAN_ITEMS = 1024u; // export
