
// Placeholder for future driver class header file

