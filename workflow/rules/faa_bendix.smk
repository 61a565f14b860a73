# Seed 003: W. Elwell (FAA Technical Center), Bendix Alpha-Beta Tracking Filter Test, and
# A. I. Sinsky's memo on the expected smoothing. Impulse and ramp responses of the eight
# gain sets, the memo's table, damping and lags.

FB = config.get("faa_bendix", {})
if "faa_bendix" in DOCS and not FB:
    raise WorkflowError("config lists faa_bendix in docs but has no faa_bendix section")


script_rule(
    "faa_bendix_figures",
    "faa_bendix_figures.py",
    input={
        t: f"results/faa_bendix/{t}.csv"
        for t in ("responses", "damping_lags", "captions")
    },
    output={
        f: report(
            f"results/faa_bendix/figures/{f}.png",
            category="FAA Bendix",
            subcategory="Figures",
            labels={"figure": label},
        )
        for f, label in (
            ("impulse", "impulse"),
            ("ramp", "ramp"),
            ("triangle", "stability triangle"),
        )
    },
    log="faa_bendix/figures",
    params={"dpi": config["figure_dpi"]},
)
