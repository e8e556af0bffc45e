"""The documentation site builds with warnings as errors, its links and anchors resolve, its
math is there, and its references cover what the code accepts.

The build needs the ``docs`` extra (part of ``test``); without it these tests skip and say
what to install. The slow test renders pages in headless Chromium (Debian's ``chromium``
package) and checks that MathJax typeset the math and that every figure loaded; it skips where
no Chromium is installed.
"""

from __future__ import annotations

import importlib.util
import os
import re
import shutil
import subprocess
import sys
from html.parser import HTMLParser
from pathlib import Path
from urllib.parse import unquote, urlsplit

import pytest

ROOT = Path(__file__).resolve().parents[1]
DOCS = ROOT / "docs"
_BUILD_MODULES = ("mkdocs", "material", "mkdocstrings", "mkdocstrings_handlers.python",
                  "pymdownx", "mathjax")
def _missing_build_modules() -> list[str]:
    missing = []
    for module in _BUILD_MODULES:
        try:
            found = importlib.util.find_spec(module) is not None
        except ModuleNotFoundError:
            found = False
        if not found:
            missing.append(module)
    return missing


needs_docs_extra = pytest.mark.skipif(
    bool(_missing_build_modules()),
    reason=f"the docs extra is not installed (missing {', '.join(_missing_build_modules())}): "
           "pip install -e '.[docs]'")


@pytest.fixture(scope="module")
def site(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """The site, built once for this module with ``mkdocs build --strict``."""
    out = tmp_path_factory.mktemp("site")
    proc = subprocess.run(
        [sys.executable, "-m", "mkdocs", "build", "--strict", "--config-file",
         str(ROOT / "mkdocs.yml"), "--site-dir", str(out)],
        cwd=ROOT, capture_output=True, text=True, timeout=600, check=False,
        env={**os.environ, "NO_MKDOCS_2_WARNING": "1"})
    assert proc.returncode == 0, f"mkdocs build --strict failed:\n{proc.stdout}\n{proc.stderr}"
    return out


class _Page(HTMLParser):
    """The ids, links, images, scripts and math elements of one HTML page."""

    def __init__(self) -> None:
        super().__init__()
        self.ids: set[str] = set()
        self.links: list[str] = []
        self.images: list[str] = []
        self.scripts: list[str] = []
        self.math = 0

    def handle_starttag(self, tag: str, attrs: list[tuple[str, str | None]]) -> None:
        values = {k: v or "" for k, v in attrs}
        if "id" in values:
            self.ids.add(values["id"])
        if tag == "a" and "href" in values:
            self.links.append(values["href"])
        if tag == "img" and "src" in values:
            self.images.append(values["src"])
        if tag == "script" and "src" in values:
            self.scripts.append(values["src"])
        if "arithmatex" in values.get("class", "").split():
            self.math += 1


def _parse(path: Path) -> _Page:
    page = _Page()
    page.feed(path.read_text(encoding="utf-8"))
    return page


def _local_target(page: Path, url: str, site: Path) -> tuple[Path, str] | None:
    """The file and fragment a relative link of ``page`` points to; None for other links."""
    parts = urlsplit(url)
    if parts.scheme or parts.netloc or url.startswith(("mailto:", "javascript:")):
        return None
    target = page if not parts.path else (page.parent / unquote(parts.path)).resolve()
    if target.is_dir():
        target = target / "index.html"
    assert target.is_relative_to(site.resolve()), f"{page}: {url} leaves the site"
    return target, unquote(parts.fragment)


@needs_docs_extra
def test_every_internal_link_and_anchor_resolves(site: Path) -> None:
    pages = sorted(site.rglob("*.html"))
    assert len(pages) >= 30, "the site has its pages"
    parsed = {p.resolve(): _parse(p) for p in pages}
    broken = []
    for path, page in parsed.items():
        if path.name == "404.html":
            continue
        for url in [*page.links, *page.images, *page.scripts]:
            found = _local_target(path, url, site)
            if found is None:
                continue
            target, fragment = found
            if not target.exists():
                broken.append(f"{path.relative_to(site.resolve())}: {url} (no such file)")
            elif fragment and target.suffix == ".html" and fragment not in parsed[target].ids:
                broken.append(f"{path.relative_to(site.resolve())}: {url} (no such anchor)")
    assert not broken, "broken links:\n" + "\n".join(broken)


@needs_docs_extra
def test_math_is_in_the_pages_and_mathjax_is_served_by_the_site(site: Path) -> None:
    for page in ("index.html", "tutorials/first-run.html",
                 "explanation/models.html", "tutorials/controlling-it.html"):
        parsed = _parse(site / page)
        assert parsed.math > 0, f"{page}: no math"
        scripts = [s for s in parsed.scripts if s.endswith("tex-svg-full.js")]
        assert scripts and not urlsplit(scripts[0]).netloc, f"{page}: MathJax not served locally"
    script = site / "assets" / "mathjax" / "tex-svg-full.js"
    assert script.stat().st_size > 1_000_000, "the whole MathJax bundle is in the site"
    assert "Apache License" in (site / "assets" / "mathjax" / "LICENSE.txt").read_text()
    html = (site / "explanation" / "models.html").read_text(encoding="utf-8")
    assert r"\sqrt{\frac{R_b R_j}{R_b - R_j}}" in html, "the TeX source reaches MathJax intact"


_NETWORK_ASSET = re.compile(
    r'<(?:script|img|iframe)\b[^>]*\bsrc="(https?:)?//[^"]*"'
    r'|<link\b(?=[^>]*\brel="(?:stylesheet|preconnect|preload|modulepreload|icon)")[^>]*'
    r'\bhref="(https?:)?//[^"]*"'
    r'|@import\s+url\((https?:)?//|fonts\.(?:googleapis|gstatic)\.com')


@needs_docs_extra
def test_site_works_offline(site: Path) -> None:
    """Opened from disk with no network: no page loads a script, stylesheet or font from
    another host, and the search index is there as a script (Material's offline plugin)."""
    fetched = [f"{p.relative_to(site)}: {m.group(0)[:120]}" for p in sorted(site.rglob("*.html"))
               for m in _NETWORK_ASSET.finditer(p.read_text(encoding="utf-8"))]
    assert not fetched, "pages fetch from the network:\n" + "\n".join(fetched[:20])
    assert (site / "search" / "search_index.js").read_text(encoding="utf-8").startswith(
        "var __index = "), "the search index is not there for file://"
    assert (site / "reference" / "api.html").is_file(), "links go to .html files, not folders"


@needs_docs_extra
def test_command_reference_lists_every_command_and_option(site: Path) -> None:
    from jointplay.cli import make_parser
    from jointplay.cli.args import add_debug_flag

    html = (site / "reference" / "cli.html").read_text(encoding="utf-8")

    def walk(parser: object, prog: str) -> None:
        import argparse

        assert isinstance(parser, argparse.ArgumentParser)
        for action in parser._actions:
            for flag in action.option_strings:
                if action.help != argparse.SUPPRESS and not isinstance(action,
                                                                       argparse._HelpAction):
                    assert f"<code>{flag}" in html, f"{prog} {flag} is not in the reference"
            if isinstance(action, argparse._SubParsersAction):
                for name, child in action.choices.items():
                    assert f"<code>{prog} {name}</code>" in html, f"{prog} {name}"
                    walk(child, f"{prog} {name}")

    parser = make_parser()
    add_debug_flag(parser)
    walk(parser, "jointplay")


@needs_docs_extra
def test_api_reference_documents_the_flat_api(site: Path) -> None:
    import jointplay

    html = (site / "reference" / "api.html").read_text(encoding="utf-8")
    public = [name for name in jointplay.__all__ if not name.startswith("_")]
    missing = [name for name in public if f'id="jointplay.{name}"' not in html]
    assert not missing, f"not in the API reference: {missing}"


@needs_docs_extra
def test_api_names_in_the_prose_link_to_their_entries(site: Path) -> None:
    """`jointplay.simulate(...)`, `Stepper`, `calibrate(...)` in a page's text link to the API
    reference's entry for that name (docs/hooks/api_links.py; autorefs resolves them)."""
    sys.path.insert(0, str(DOCS / "hooks"))
    try:
        from api_links import link_names, public_names
    finally:
        sys.path.pop(0)
    names = public_names(ROOT / "runtime" / "__init__.py")
    import jointplay

    assert names == {n for n in jointplay.__all__ if not n.startswith("_")}
    text = "Call `jointplay.simulate(scene)` or `read(path)`; a `Stepper`, not `simulate`.\n"
    assert link_names(text, names) == (
        "Call [`jointplay.simulate(scene)`][jointplay.simulate] or [`read(path)`][jointplay.read];"
        " a [`Stepper`][jointplay.Stepper], not `simulate`.\n")
    assert link_names("```python\n`Stepper`\n```\n# `Stepper`\n", names) == \
        "```python\n`Stepper`\n```\n# `Stepper`\n"
    linked = [p for p in site.rglob("*.html") if p.name != "api.html"
              and re.search(r'href="[^"]*api\.html#jointplay\.\w+"', p.read_text("utf-8"))]
    assert len(linked) >= 10, f"only {len(linked)} pages link names to the API reference"


def test_file_references_list_every_key() -> None:
    """Every key a robot or scene file accepts appears in its reference page."""
    from jointplay.robot import description, reading
    from jointplay.scene import definition

    robot_page = (DOCS / "reference" / "robot-file.md").read_text(encoding="utf-8")
    tables = {"contact": description.Contact(), "friction": description.Friction(),
              "lubrication": description.Lubrication(), "wear": description.Wear()}
    keys = [*reading._TOP_KEYS, *(f"links.{k}" for k in reading._LINK_KEYS),
            *(f"joints.{k}" for k in reading._JOINT_KEYS), "payload.mass", "gravity.enabled",
            "gravity.vector", "drive.enabled",
            *(f"{table}.{k}" for table, value in tables.items() for k in vars(value))]
    missing = [k for k in keys  # a table is documented by its keys: `payload.mass`
               if not any(form in robot_page for form in (f"`{k}`", f"`[[{k}]]`", f"`{k}."))]
    assert not missing, f"robot keys missing from docs/reference/robot-file.md: {missing}"
    scene_page = (DOCS / "reference" / "scene-file.md").read_text(encoding="utf-8")
    keys = [k for k in definition._TOP_KEYS if k not in ("constants", "torques", "initial", "run")]
    keys += ["[constants]", "[torques]", "[initial]", "initial.journals", "torques.hold_ends",
             *(f"run.{k}" for k in definition._RUN_KEYS)]
    missing = [k for k in keys if f"`{k}`" not in scene_page]
    assert not missing, f"scene keys missing from docs/reference/scene-file.md: {missing}"


def test_every_page_is_in_the_navigation_or_known_to_come() -> None:
    """A page left out of mkdocs.yml's nav (and not listed under not_in_nav) fails the strict
    build; this says which, without building."""
    config = (ROOT / "mkdocs.yml").read_text(encoding="utf-8")
    pages = [p.relative_to(DOCS).as_posix() for p in DOCS.rglob("*.md")]
    missing = [p for p in pages
               if re.search(rf"(^|\s)/?{re.escape(p)}\s*$", config, re.M) is None]
    assert not missing, f"add these pages to the nav of mkdocs.yml: {missing}"


# ---- in a real browser -----------------------------------------------------------------------

_CHROMIUM = shutil.which("chromium") or shutil.which("chromium-browser")
# CI installs Chromium and sets this, so there the browser test fails rather than skips.
_BROWSER_REQUIRED = os.environ.get("JOINTPLAY_REQUIRE_BROWSER") == "1"
# After the page's own scripts: count the figures that loaded and the math MathJax typeset,
# then type a word into the search box and count the results (the index is read from file://).
_PROBE = """<script>
window.addEventListener("load", () => setTimeout(() => {
  const images = [...document.querySelectorAll("article img")];
  const loaded = images.filter((i) => i.complete && i.naturalWidth > 0).length;
  const math = document.querySelectorAll("article .arithmatex").length;
  const typeset = [...document.querySelectorAll("article .arithmatex mjx-container")]
    .filter((c) => c.querySelector("svg")).length;  // one per formula (an svg may nest others)
  const errors = document.querySelectorAll("article mjx-merror").length;
  const input = document.querySelector(".md-search__input");
  if (input) {
    input.focus();
    input.value = "clearance";
    input.dispatchEvent(new Event("input", {bubbles: true}));
    input.dispatchEvent(new KeyboardEvent("keyup", {bubbles: true}));
  }
  setTimeout(() => {
    const hits = document.querySelectorAll(".md-search-result__item").length;
    document.body.setAttribute("data-probe",
      `images=${loaded}/${images.length} math=${typeset}/${math} errors=${errors} hits=${hits}`);
  }, 3000);
}, 3000));
</script>"""


def _render(page: Path, tmp: Path) -> dict[str, int | tuple[int, int]]:
    """Load ``page`` from disk in headless Chromium (no network) and read the probe."""
    assert _CHROMIUM is not None
    probe = page.with_name("probe.html")
    html = page.read_text(encoding="utf-8").replace("</body>", _PROBE + "</body>")
    probe.write_text(html, encoding="utf-8")
    flags = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
             "--disable-background-networking", "--disable-component-update", "--disable-sync",
             "--allow-file-access-from-files", f"--user-data-dir={tmp / 'profile'}",
             "--window-size=1280,2000", "--virtual-time-budget=20000"]
    shot = tmp / f"{page.parent.name}-{page.stem}.png"
    subprocess.run([_CHROMIUM, *flags, f"--screenshot={shot}", probe.as_uri()],
                   capture_output=True, timeout=180, check=False)
    dom = subprocess.run([_CHROMIUM, *flags, "--dump-dom", probe.as_uri()],
                         capture_output=True, text=True, timeout=180, check=False).stdout
    probe.unlink()
    found = re.search(r'data-probe="images=(\d+)/(\d+) math=(\d+)/(\d+) errors=(\d+) '
                      r'hits=(\d+)"', dom)
    assert found, f"{page}: the page did not finish loading in Chromium"
    images_loaded, images, typeset, math, errors, hits = map(int, found.groups())
    assert shot.stat().st_size > 10_000, f"{shot}: an empty screenshot"
    return {"images": (images_loaded, images), "math": (typeset, math), "errors": errors,
            "hits": hits}


@pytest.mark.slow
@needs_docs_extra
def test_pages_render_their_math_and_figures_in_chromium(site: Path, tmp_path: Path) -> None:
    if _CHROMIUM is None:
        message = "no Chromium installed (apt-get install chromium)"
        if _BROWSER_REQUIRED:
            pytest.fail(f"JOINTPLAY_REQUIRE_BROWSER=1 but {message}")
        pytest.skip(message)
    expected = {"index.html": True, "tutorials/first-run.html": True,
                "explanation/controller.html": True, "gallery.html": False,
                "results/control.html": False, "reference/api.html": False}
    for page, has_math_and_figures in expected.items():
        seen = _render(site / page, tmp_path)
        loaded, images = seen["images"]  # type: ignore[misc]
        typeset, math = seen["math"]  # type: ignore[misc]
        assert loaded == images, f"{page}: {images - loaded} of {images} figures did not load"
        assert typeset == math, f"{page}: MathJax typeset {typeset} of {math} formulas"
        assert seen["errors"] == 0, f"{page}: MathJax reported errors"
        assert seen["hits"] != 0, f"{page}: the search box found nothing from file://"
        if has_math_and_figures:
            assert images >= 1 and math >= 1, (page, seen)
    api = (site / "reference" / "api.html").read_text(encoding="utf-8")
    assert api.count('class="doc doc-object') >= 40, "the API reference has its entries"


def test_site_home_shows_the_readme_commands() -> None:
    """The home page repeats the README's two commands (shown, not run): they stay the same."""
    readme = (ROOT / "README.md").read_text(encoding="utf-8")
    home = (DOCS / "index.md").read_text(encoding="utf-8")
    commands = re.findall(r"<!-- docs: ci -->\n```sh\n(?:#.*\n)*(.+)\n```", readme)
    assert len(commands) == 2, "the README's first screen has two commands"
    for command in commands:
        assert command in home, f"docs/index.md does not show the README's `{command}`"


def test_changelog_citation_and_licence() -> None:
    """CHANGELOG.md is in Keep a Changelog form and shown on the site; CITATION.cff carries the
    fields citation-file-format 1.2.0 requires; LICENSE is the licence pyproject.toml names;
    the method's paper is cited with the same DOI on the landing page and in the
    controller's explanation."""
    yaml = pytest.importorskip("yaml")
    changelog = (ROOT / "CHANGELOG.md").read_text(encoding="utf-8")
    assert changelog.startswith("# Changelog\n") and "keepachangelog.com" in changelog
    assert "## [Unreleased]" in changelog
    assert '--8<-- "CHANGELOG.md"' in (DOCS / "changelog.md").read_text(encoding="utf-8")
    citation = yaml.safe_load((ROOT / "CITATION.cff").read_text(encoding="utf-8"))
    assert citation["cff-version"] == "1.2.0"
    assert {"message", "title", "authors"} <= set(citation) and citation["authors"]
    assert citation["license"] == "MIT"
    assert (ROOT / "LICENSE").read_text(encoding="utf-8").startswith("MIT License")
    assert 'license = { text = "MIT" }' in (ROOT / "pyproject.toml").read_text(encoding="utf-8")
    doi = "10.1177/1687814018812320"
    for page in ("index.md", "explanation/controller.md"):
        assert f"https://doi.org/{doi}" in (DOCS / page).read_text(encoding="utf-8"), page
    assert doi in citation["message"]
