"""A Sphinx extension for the course website: pages that work offline with a clean console.

- Every script is included once. Jupyter Book v1's extensions add some inline scripts twice
  under Sphinx 7 (sphinx-thebe's ``const THEBE_JS_URL`` then fails to redeclare, an error in the
  console of every page).
- No Thebe: the site runs no code in the page (the launch buttons open Binder or JupyterHub
  instead), so sphinx-thebe's loader, which would fetch Thebe from a CDN, is left out.
"""

from __future__ import annotations


def _thebe(asset) -> bool:
    text = f"{asset.filename} {asset.attributes.get('body', '')}"
    return "thebe" in text.lower()


def _clean(app, pagename, templatename, context, doctree) -> None:
    for key in ("script_files", "css_files"):
        assets, seen = [], set()
        for asset in context.get(key, []):
            if asset in seen or _thebe(asset):
                continue
            seen.add(asset)
            assets.append(asset)
        context[key] = assets


def setup(app):
    app.connect("html-page-context", _clean, priority=900)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
