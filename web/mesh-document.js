// SPDX-License-Identifier: GPL-3.0-or-later
//
// What the playground (web/mesh-assembly.js) and the drop-in viewer (web/viewer.js) share about
// mesh assemblies (issue 29, docs/meshes.md): which files are read as parts, and the document the
// view, the report and the parts panel are given for one.

/** Files the core reads as parts of a mesh assembly (the CLI's rule: by the extension). */
export function isMeshAssemblyName(name) {
  return /\.(obj|stl|3mf)$/i.test(name ?? '');
}

/**
 * The document drawn for a mesh assembly's check report: kind 'mesh', each part with its own name
 * (the report's mesh.partNames: OBJ object or group, STL solid or file, 3MF object).
 */
export function meshViewDocument(name, report) {
  const names = report.mesh?.partNames ?? [];
  return { kind: 'mesh', name, parts: report.partIds.map((id, k) => ({ id, name: names[k] ?? `part ${id}` })) };
}
