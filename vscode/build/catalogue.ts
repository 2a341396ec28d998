/**
 * Generates the builtins' catalogue (src/analyzer/catalogue.ts) from the
 * book's TypeScript: the entries of `createLibrary` in widgets/catalogue.ts,
 * each with the comment above it, the signature of the value it loads and,
 * for parameters that are options objects, their properties with their own
 * doc comments and types (nested options objects included). Nothing is
 * listed by hand: a new widget or option shows up in completion and hover
 * at the next build.
 */
import path from 'node:path';
import ts from 'typescript';
import type { Catalogue, CatalogueEntry, CatalogueOption, CatalogueParameter } from '../src/analyzer/catalogue.ts';

/** How deep options objects inside options objects are followed (simulator → timePlot → …). */
const MAX_DEPTH = 3;

/**
 * An options object is a parameter or property whose type is an object
 * literal type or an interface named `…Options` or `…Spec`: a `Model` or a
 * `Float64Array` has properties too, but a cell never writes them out.
 */
function isOptionsType(type: ts.Type): boolean {
  if (!(type.flags & ts.TypeFlags.Object) || type.getCallSignatures().length || type.getConstructSignatures().length) return false;
  if (type.getProperties().length === 0) return false;
  const name = type.aliasSymbol?.name ?? type.getSymbol()?.name ?? '';
  return name === '__type' || name === '__object' || /(Options|Spec)$/.test(name);
}

function docOf(symbol: ts.Symbol, checker: ts.TypeChecker): string {
  return ts.displayPartsToString(symbol.getDocumentationComment(checker)).trim();
}

function optionsOf(type: ts.Type, checker: ts.TypeChecker, depth: number): CatalogueOption[] | undefined {
  const object = checker.getNonNullableType(type);
  if (depth > MAX_DEPTH || !isOptionsType(object)) return undefined;
  return object.getProperties().map((property) => {
    const declaration = property.valueDeclaration ?? property.declarations?.[0];
    const propertyType = declaration ? checker.getTypeOfSymbolAtLocation(property, declaration) : checker.getTypeOfSymbol(property);
    const options = optionsOf(propertyType, checker, depth + 1);
    return {
      name: property.name,
      type: checker.typeToString(checker.getNonNullableType(propertyType)),
      optional: (property.flags & ts.SymbolFlags.Optional) !== 0,
      doc: docOf(property, checker),
      ...(options ? { options } : {}),
    };
  });
}

function parametersOf(signature: ts.Signature, checker: ts.TypeChecker, at: ts.Node): CatalogueParameter[] {
  return signature.getParameters().map((parameter) => {
    const type = checker.getTypeOfSymbolAtLocation(parameter, at);
    const declaration = parameter.valueDeclaration;
    const optional = !!declaration && ts.isParameter(declaration) && (!!declaration.questionToken || !!declaration.initializer);
    const options = optionsOf(type, checker, 1);
    return { name: parameter.name, type: checker.typeToString(checker.getNonNullableType(type)), optional, ...(options ? { options } : {}) };
  });
}

/** The value an entry loads: every entry is a loader, `() => import(…).then(…)`, and this is the awaited type of what it returns. */
function loadedType(type: ts.Type, checker: ts.TypeChecker): ts.Type {
  const [signature] = type.getCallSignatures();
  if (!signature) return type;
  return checker.getAwaitedType(signature.getReturnType()) ?? signature.getReturnType();
}

function describeEntry(property: ts.PropertyAssignment, checker: ts.TypeChecker): CatalogueEntry {
  const name = property.name.getText();
  const symbol = checker.getSymbolAtLocation(property.name);
  const doc = symbol ? docOf(symbol, checker) : '';
  const value = loadedType(checker.getTypeAtLocation(property.initializer), checker);
  const [construct] = value.getConstructSignatures();
  if (construct) {
    const parameters = parametersOf(construct, checker, property);
    return { name, doc, kind: 'class', signature: `new ${name}(${parameters.map(show).join(', ')})`, parameters };
  }
  const [call] = value.getCallSignatures();
  if (call) {
    const parameters = parametersOf(call, checker, property);
    const returns = checker.typeToString(call.getReturnType());
    return { name, doc, kind: 'function', signature: `${name}(${parameters.map(show).join(', ')}): ${returns}`, parameters };
  }
  return { name, doc, kind: 'value', signature: `${name}: ${checker.typeToString(value)}`, parameters: [] };
}

function show(parameter: CatalogueParameter): string {
  return `${parameter.name}${parameter.optional ? '?' : ''}: ${parameter.type}`;
}

/** The object literal `createLibrary` returns. */
function libraryObject(source: ts.SourceFile): ts.ObjectLiteralExpression {
  let found: ts.ObjectLiteralExpression | undefined;
  const visit = (node: ts.Node): void => {
    if (ts.isFunctionDeclaration(node) && node.name?.text === 'createLibrary') {
      node.body?.statements.forEach((statement) => {
        if (ts.isReturnStatement(statement) && statement.expression && ts.isObjectLiteralExpression(statement.expression)) found = statement.expression;
      });
    }
    ts.forEachChild(node, visit);
  };
  visit(source);
  if (!found) throw new Error(`${source.fileName}: createLibrary no longer returns an object literal; vscode/build/catalogue.ts reads it`);
  return found;
}

/** The catalogue of the book whose root folder is `root`. */
export function generateCatalogue(root: string): Catalogue {
  const file = path.join(root, 'widgets', 'catalogue.ts');
  const program = ts.createProgram([file], {
    target: ts.ScriptTarget.ES2022,
    module: ts.ModuleKind.ESNext,
    moduleResolution: ts.ModuleResolutionKind.Bundler,
    allowImportingTsExtensions: true,
    strict: true,
    noEmit: true,
    skipLibCheck: true,
    lib: ['lib.es2022.d.ts', 'lib.dom.d.ts', 'lib.dom.iterable.d.ts'],
    types: [],
  });
  const source = program.getSourceFile(file);
  if (!source) throw new Error(`cannot read ${file}`);
  const checker = program.getTypeChecker();
  const builtins = libraryObject(source).properties.filter(ts.isPropertyAssignment).map((property) => describeEntry(property, checker));
  return { builtins };
}
