/**
 * Cells' runtime errors, as the preview reports them, as diagnostics on the
 * failing cell's first line of code. A cell that already has an error of
 * the analyzer (a syntax error, an unknown name, a duplicate) gets none:
 * its runtime error is that same problem seen again.
 */
import * as vscode from 'vscode';
import type { ChapterAnalysis } from '../../analyzer/analyze.ts';
import type { CellReport } from '../../shared/messages.ts';

export const RUNTIME_SOURCE = 'Phasebook preview';

export function runtimeDiagnostics(reports: readonly CellReport[], analysis: ChapterAnalysis): vscode.Diagnostic[] {
  const staticErrors = analysis.problems.filter((p) => p.severity === 'error');
  return reports.flatMap((report) => {
    if (report.state !== 'rejected' || !report.error) return [];
    const cell = analysis.cells.find((c) => c.id === report.id);
    if (cell && staticErrors.some((p) => p.start >= cell.start && p.start <= cell.end)) return [];
    const line = Math.min(report.line + 1, Math.max(report.line, report.endLine - 1));
    const end = analysis.lines.lineEnd(line) - analysis.lines.offset(line, 0);
    const diagnostic = new vscode.Diagnostic(new vscode.Range(line, 0, line, end), report.error, vscode.DiagnosticSeverity.Error);
    diagnostic.source = RUNTIME_SOURCE;
    diagnostic.code = 'runtime-error';
    return [diagnostic];
  });
}
