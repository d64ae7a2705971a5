// The audit's entries for Appendix A: T, A, B, C, f1..f8 and the coefficients a1..c3.
#include "audit_checks.hpp"
#include "audit_parts.hpp"
#include "codegen.hpp"
#include "paper.hpp"

namespace impact3d::symbolic {

using namespace GiNaC;

void audit_appendix_a(std::vector<AuditEntry>& out, const AppendixA& a) {
  {
    const ex cg = sym("cg"), sg = sym("sg"), ct = sym("ct"), st = sym("st"), cp = sym("cp"), sp = sym("sp");
    const matrix T = paper::appendix_T(cg, sg, ct, st, cp, sp);
    // The contract's rotation: T = Rx(-phi) Ry(-theta) Rz(-gamma) (vehicle -> contact).
    const matrix Rx(3, 3, lst{1, 0, 0, 0, cp, sp, 0, -sp, cp});
    const matrix Ry(3, 3, lst{ct, 0, -st, 0, 1, 0, st, 0, ct});
    const matrix Rz(3, 3, lst{cg, sg, 0, -sg, cg, 0, 0, 0, 1});
    const matrix R = Rx.mul(Ry).mul(Rz);
    AuditEntry e = formula(
        "A.T",
        "The printed T(gamma, theta, phi), entry by entry, against Rx(-phi) Ry(-theta) Rz(-gamma): the "
        "contract's R_c^T R_i for a level vehicle with gamma = normal_yaw - yaw, theta = normal_pitch, "
        "phi = tangent_roll (rows n, t, z; columns the vehicle's x, y, z).",
        {});
    const char* axis_row[3] = {"n", "t", "z"};
    const char* axis_col[3] = {"x", "y", "z"};
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        e.checks.push_back(Auditor::compare(std::string("row ") + axis_row[i] + ", column " + axis_col[j], T(i, j), R(i, j),
                                            all_angles()));
    std::string rows;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) rows += tex(T(i, j)) + (j < 2 ? " & " : i < 2 ? " \\\\ " : "");
    e.printed_latex = "T = \\begin{bmatrix} " + rows + " \\end{bmatrix}";
    out.push_back(std::move(e));
  }
  const auto definitions = paper::appendix_definitions();
  for (const char* item : {"A", "B", "C", "f1", "f2", "f3", "f4", "f5", "f6", "f7", "f8"}) {
    out.push_back(formula(std::string("A.") + item,
                          std::string("Appendix A's ") + item + " against the derivation's grouping of K's entries.",
                          {Auditor::compare(item, definitions.at(item), a.derived.at(item), a.angles)},
                          tex(definitions.at(item))));
  }
  const exmap defs = paper::appendix_definitions_map();
  const auto printed = paper::appendix_coefficients(), corrected = paper::appendix_coefficients_corrected();
  const std::map<std::string, std::string> entry_of_K = {
      {"a1", "row n, column n"}, {"a2", "row t, column n"}, {"a3", "row z, column n"},
      {"b1", "row n, column t"}, {"b2", "row t, column t"}, {"b3", "row z, column t"},
      {"c1", "row n, column z"}, {"c2", "row t, column z"}, {"c3", "row z, column z"}};
  for (const char* item : {"a1", "a2", "a3", "b1", "b2", "b3", "c1", "c2", "c3"}) {
    AuditEntry e = formula(std::string("A.") + item,
                           std::string("Appendix A's ") + item + " (K's " + entry_of_K.at(item) +
                               "), with the printed A, B, C, f1..f8 expanded, against the derivation at theta = 0.",
                           {Auditor::compare(item, printed.at(item).subs(defs), a.derived.at(item), a.angles)},
                           tex(printed.at(item)));
    if (!(printed.at(item) - corrected.at(item)).is_zero()) {
      e.corrections.push_back(
          Auditor::compare(std::string(item) + ", corrected", corrected.at(item).subs(defs), a.derived.at(item), a.angles));
      e.corrected_latex = tex(corrected.at(item));
      e.detail += " The correction flips the sign of f_8 in c_3 (f_8 as printed, and as b_3 uses it): as printed, the "
                  "yaw-inertia term lowers c_3 although K is I plus a positive semidefinite matrix.";
    }
    out.push_back(std::move(e));
  }
}

}  // namespace impact3d::symbolic
