/** Types of cli-bundle.mjs, for the tests and benchmarks that build and locate the compiled CLI. */
export interface BuildOptions {
  /** where the bundle goes; build/cli/ by default */
  outDir?: string;
  /** the project root its inputs are relative to */
  root?: string;
  /** empty outDir first */
  clean?: boolean;
}
export declare const ROOT: string;
export declare const OUT_DIR: string;
export declare function freshEntry(outDir?: string, root?: string): string | undefined;
export declare function buildCli(options?: BuildOptions): Promise<string>;
export declare function ensureCli(options?: BuildOptions): Promise<string>;
