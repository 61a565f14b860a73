"""Write the stylesheet and script shared by every report of a version (``assets/``)."""

from pathlib import Path

from abglib.common.jobs import log_to


def main(output) -> None:
    from abglib.reporting.render import write_assets

    written = {p.name for p in write_assets(Path(output.css).parent)}
    missing = {Path(output.css).name, Path(output.js).name} - written
    if missing:
        raise FileNotFoundError(f"abglib/reporting/assets lacks {sorted(missing)}")


if "snakemake" in globals():
    log_to(snakemake.log[0])  # noqa: F821
    main(snakemake.output)  # noqa: F821
