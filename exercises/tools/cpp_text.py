"""cpp_text: C++ source read as tokens, enough to judge an exercise region as text.

A region a student writes is put into the instructor's copy of the library between
its markers, inside a function the instructor wrote. So that it stays there, the
autograder and the grader take it only if it reads as statements of that function:

  - no preprocessor line (`#include` would read any file while compiling, `#define`
    could rewrite the instructor's code after the region): no `#`, `%:` or `??=`;
  - braces that never close the function's own `{` and that all close by the END
    marker: no `}` that ends the function, so no code at namespace scope (a global
    object whose constructor runs before main, a second definition of a function);
  - no `asm` and no `_Pragma`;
  - no attribute but the standard ones a statement may carry (`[[maybe_unused]]`,
    `[[likely]]`, `[[fallthrough]]`, ...), and no `__attribute__` or `__declspec`: a
    static local marked `[[gnu::used, gnu::section(".preinit_array")]]` would run
    before main, ahead of the harness that takes the grader's key;
  - every comment, string and character literal closed inside the region, and no
    line splice (`\\` at the end of a line) on its last line, so that nothing after
    the END marker is swallowed. A splice is read as GCC reads it: a backslash, then
    spaces or tabs, then the end of the line.

The same reading finds the parameters of the function a region sits in, which a
kit's stub names so that it compiles without "unused parameter" warnings.
"""
import re
from dataclasses import dataclass

IDENTIFIER = re.compile(r"[A-Za-z_\$][A-Za-z0-9_\$]*")
NUMBER = re.compile(r"\.?[0-9](?:[eEpP][+-]|'[0-9A-Za-z_]|[0-9A-Za-z_.])*")
STRING_PREFIX = re.compile(r"(?:u8|u|U|L)?R?(?=[\"'])")
# Longest first: a digraph or a three-character punctuator before its prefix.
PUNCTUATORS = sorted("""%:%: ... <=> ->* <<= >>= :: -> ++ -- << >> <= >= == != && || += -= *= /= %= &= |= ^= .*
<% %> <: :> %: ## # { } [ ] ( ) ; : ? . , ~ ! + - * / % ^ & | = < >""".split(), key=len, reverse=True)
BANNED_WORDS = {"asm", "__asm", "__asm__", "_Pragma", "__pragma", "__attribute__", "__attribute", "__declspec"}
# The attributes C++20 gives statements and local declarations; any other (a vendor's
# gnu::section, gnu::constructor, gnu::used, ...) is refused.
STANDARD_ATTRIBUTES = {"maybe_unused", "likely", "unlikely", "fallthrough", "nodiscard", "noreturn", "deprecated",
                       "carries_dependency", "no_unique_address", "assume"}
SPLICE = re.compile(r"\\[ \t]*(\r?\n)")  # GCC splices across trailing blanks (with a warning)
OPEN, CLOSE = {"{", "<%"}, {"}", "%>"}


class TextError(Exception):
    """The text is not a region the grader takes: the message says why, with the line."""


@dataclass
class Token:
    kind: str   # "word", "number", "string", "punct"
    text: str
    line: int   # 1-based, in the text given


def spliced(text):
    """The text with line splices removed, and for each character left the line it came from."""
    chars, lines, line, k = [], [], 1, 0
    while k < len(text):
        splice = SPLICE.match(text, k) if text[k] == "\\" else None
        if splice:
            k, line = splice.end(), line + 1
            continue
        chars.append(text[k])
        lines.append(line)
        if text[k] == "\n":
            line += 1
        k += 1
    return "".join(chars), lines


def tokens(text):
    """The tokens of C++ text (comments dropped); TextError on a comment or literal left open."""
    source, line_of = spliced(text)
    found, k, n = [], 0, len(source)
    while k < n:
        c = source[k]
        line = line_of[k]
        if c.isspace():
            k += 1
        elif source.startswith("//", k):
            end = source.find("\n", k)
            k = n if end < 0 else end
        elif source.startswith("/*", k):
            end = source.find("*/", k + 2)
            if end < 0:
                raise TextError(f"line {line}: a /* comment is not closed")
            k = end + 2
        elif (prefix := STRING_PREFIX.match(source, k)) is not None and (prefix.group() or c in "\"'") \
                and not (prefix.group() and k > 0 and (source[k - 1].isalnum() or source[k - 1] == "_")):
            start = prefix.end()
            if prefix.group().endswith("R") and source[start] == '"':
                opening = source.find("(", start)
                delimiter = source[start + 1:opening] if opening >= 0 else None
                if delimiter is None or len(delimiter) > 16 or any(ch in delimiter for ch in " \\)\t\n"):
                    raise TextError(f"line {line}: a raw string literal with a malformed delimiter")
                end = source.find(")" + delimiter + '"', opening)
                if end < 0:
                    raise TextError(f"line {line}: a raw string literal is not closed")
                k = end + len(delimiter) + 2
            else:
                quote, j = source[start], start + 1
                while j < n and source[j] != quote and source[j] != "\n":
                    j += 2 if source[j] == "\\" else 1
                if j >= n or source[j] != quote:
                    kind = "string" if quote == '"' else "character"
                    raise TextError(f"line {line}: a {kind} literal is not closed")
                k = j + 1
            found.append(Token("string", source[prefix.start():k], line))
        elif (m := NUMBER.match(source, k)) is not None:
            found.append(Token("number", m.group(), line))
            k = m.end()
        elif (m := IDENTIFIER.match(source, k)) is not None:
            found.append(Token("word", m.group(), line))
            k = m.end()
        else:
            punct = next((p for p in PUNCTUATORS if source.startswith(p, k)), c)
            if punct == "<:" and source.startswith("<::", k) and not source.startswith(("<:::", "<::>"), k):
                punct = "<"  # C++11: "<::" is "<" then "::", as in vector<::T>
            found.append(Token("punct", punct, line))
            k += len(punct)
    return found


def check_body(text):
    """Raises TextError unless `text` reads as statements inside a function body."""
    lines = text.splitlines()
    if lines and lines[-1].rstrip(" \t\r").endswith("\\"):
        raise TextError(f"line {len(lines)}: a line splice (\\ at the end) on the region's last line")
    for number, line in enumerate(lines, 1):
        if "??=" in line or "??<" in line or "??>" in line:
            # C++17 has no trigraphs, but an older compiler mode would read ??= as #.
            code = line.split("//")[0]
            if "??" in code and '"' not in code:
                raise TextError(f"line {number}: a trigraph (??=, ??<, ??>) stands for a preprocessor or brace token")
    depth = 0
    found = tokens(text)
    for k, token in enumerate(found):
        if is_open_bracket(token) and k + 1 < len(found) and is_open_bracket(found[k + 1]):
            check_attributes(found, k + 2)
        if token.kind == "punct" and token.text in ("#", "%:", "##", "%:%:"):
            raise TextError(f"line {token.line}: a preprocessor line ('{token.text}'): a region holds statements only")
        if token.kind == "word" and token.text in BANNED_WORDS:
            raise TextError(f"line {token.line}: '{token.text}' is not allowed in a region")
        if token.kind == "word" and token.text in ("import", "module", "export"):
            raise TextError(f"line {token.line}: '{token.text}' (a module declaration) is not allowed in a region")
        if token.kind == "punct" and token.text in OPEN:
            depth += 1
        elif token.kind == "punct" and token.text in CLOSE:
            depth -= 1
            if depth < 0:
                raise TextError(f"line {token.line}: this '{token.text}' closes the function the region sits in: "
                                "code after it would run outside the function")
    if depth > 0:
        raise TextError(f"{depth} brace(s) opened in the region are not closed before its END marker")


def is_open_bracket(token):
    return token.kind == "punct" and token.text in ("[", "<:")


def check_attributes(found, k):
    """Raises TextError unless the attribute list [[ ... ]] from token k holds only
    standard attributes (no namespace such as gnu::, no `using`)."""
    depth = 0
    for token in found[k:]:
        if token.kind == "punct" and token.text in ("[", "<:", "(", "{", "<%"):
            depth += 1
        elif token.kind == "punct" and token.text in ("]", ":>", ")", "}", "%>"):
            if depth == 0:
                return
            depth -= 1
        elif depth == 0 and token.kind == "word" and token.text not in STANDARD_ATTRIBUTES:
            raise TextError(f"line {token.line}: the attribute '{token.text}' is not allowed in a region "
                            "(only the standard ones: " + ", ".join(sorted(STANDARD_ATTRIBUTES)) + ")")
        elif depth == 0 and token.kind == "punct" and token.text == "::":
            raise TextError(f"line {token.line}: a vendor's attribute ('::') is not allowed in a region")


CONTROL = {"if", "for", "while", "switch", "catch", "return", "sizeof", "alignof", "decltype", "noexcept",
           "requires", "static_assert", "constexpr", "consteval"}


def enclosing_parameters(text, line_index):
    """The names of the parameters of the innermost function (or lambda) whose body
    holds line `line_index` (0-based) of `text` -- a pack as `name...` -- or [] when
    the line is in no function."""
    before = "".join(text.splitlines(keepends=True)[:line_index])
    try:
        found = tokens(before)
    except TextError:
        return []
    stack = []  # per open brace: the parameter names if it opens a function body, else None
    for k, token in enumerate(found):
        if token.kind == "punct" and token.text in OPEN:
            stack.append(function_parameters(found, k))
        elif token.kind == "punct" and token.text in CLOSE and stack:
            stack.pop()
    return next((names for names in reversed(stack) if names is not None), [])


QUALIFIERS = {"const", "noexcept", "override", "final", "mutable", "volatile", "constexpr"}


def function_parameters(found, brace):
    """If the brace at index `brace` opens a function or lambda body, its parameter
    names (possibly none); otherwise None. (A constructor's member-initialiser list
    is not recognised: its body counts as no function.)"""
    k = brace - 1
    while k >= 0 and found[k].kind == "word" and found[k].text in QUALIFIERS:
        k -= 1
    if k >= 0 and found[k].text != ")":  # perhaps a trailing return type: ") -> type {"
        j = k
        while j >= 0 and found[j].text not in ("->", ";", "{", "}", "<%", "%>"):
            j -= 1
        if j < 0 or found[j].text != "->":
            return None
        k = j - 1
        while k >= 0 and found[k].kind == "word" and found[k].text in QUALIFIERS:
            k -= 1
    if k < 0 or found[k].text != ")":
        return None
    close, depth = k, 0
    while k >= 0:
        if found[k].kind == "punct":
            depth += {")": 1, "(": -1}.get(found[k].text, 0)
        if depth == 0:
            break
        k -= 1
    if k <= 0:
        return None
    head = found[k - 1]
    if head.kind == "word" and head.text in CONTROL:
        return None
    if not (head.kind == "word" or head.text in ("]", ">")):
        return None
    return parameter_names(found[k + 1:close])


def parameter_names(inside):
    """Names from the tokens between a parameter list's parentheses."""
    names, current, depth = [], [], 0
    for token in inside + [Token("punct", ",", 0)]:
        if token.kind == "punct" and token.text in ("(", "[", "{", "<"):
            depth += 1
        elif token.kind == "punct" and token.text in (")", "]", "}", ">"):
            depth -= 1
        elif token.kind == "punct" and token.text == ">>":
            depth -= 2
        if token.kind == "punct" and token.text == "," and depth == 0:
            names.append(declared_name(current))
            current = []
        else:
            current.append(token)
    return [n for n in names if n]


TYPE_WORDS = {"void", "bool", "char", "wchar_t", "char8_t", "char16_t", "char32_t", "short", "int", "long", "signed",
              "unsigned", "float", "double", "auto", "const", "volatile"}


def declared_name(declaration):
    """The name a parameter declaration introduces ("" if it has none): its last
    token, when that is a word after some type (`const Ray& ray`, `int n`), not a
    type itself (`int`, `const Ray&`, `const Sphere`)."""
    texts = [t.text for t in declaration]
    if "=" in texts:  # a default argument
        declaration = declaration[:texts.index("=")]
    if len(declaration) < 2 or declaration[-1].kind != "word" or declaration[-1].text in TYPE_WORDS:
        return ""
    if all(t.kind == "word" and t.text in ("const", "volatile") for t in declaration[:-1]):
        return ""  # "const Sphere": a type without a name
    name = declaration[-1].text
    return name + "..." if any(t.text == "..." for t in declaration) else name
