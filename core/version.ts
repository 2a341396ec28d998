/** The package version written into every export, so a file says what made it. */
export const VERSION = '0.1.0';
