/**
 * The analyzer's problems as VS Code diagnostics. Offsets become positions
 * through the analysed text's own line index, so a chapter read from disk
 * (never opened) gets the same positions as an open one.
 */
import * as vscode from 'vscode';
import type { LineIndex } from '../analyzer/positions.ts';
import type { Problem } from '../analyzer/problems.ts';

export const DIAGNOSTIC_SOURCE = 'Phasebook';

export function rangeOf(lines: LineIndex, start: number, end: number): vscode.Range {
  const from = lines.position(start);
  const to = lines.position(Math.max(start, end));
  return new vscode.Range(from.line, from.character, to.line, to.character);
}

/** `linesOf` finds the line index of another file named by a related place. */
export function toDiagnostic(
  problem: Problem,
  uri: vscode.Uri,
  lines: LineIndex,
  linesOf: (file: string) => LineIndex | undefined,
): vscode.Diagnostic {
  const severity = problem.severity === 'error' ? vscode.DiagnosticSeverity.Error : vscode.DiagnosticSeverity.Warning;
  const diagnostic = new vscode.Diagnostic(rangeOf(lines, problem.start, problem.end), problem.message, severity);
  diagnostic.source = DIAGNOSTIC_SOURCE;
  diagnostic.code = problem.code;
  diagnostic.relatedInformation = (problem.related ?? []).flatMap((related) => {
    const target = related.file ? vscode.Uri.parse(related.file) : uri;
    const targetLines = related.file ? linesOf(related.file) : lines;
    return targetLines ? [new vscode.DiagnosticRelatedInformation(new vscode.Location(target, rangeOf(targetLines, related.start, related.end)), related.message)] : [];
  });
  return diagnostic;
}
