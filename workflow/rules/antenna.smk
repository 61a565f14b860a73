# Seed 004: LQ preview control and Kalman estimation for a radar tracking antenna. The
# model's parameter values are lost in the scan; config.yaml's antenna.parameters holds the
# reconstruction, the report the reasoning.

AN = config.get("antenna", {})
if "antenna" in DOCS and not AN:
    raise WorkflowError("config lists antenna in docs but has no antenna section")


script_rule(
    "antenna_figures",
    "antenna_figures.py",
    input={t: f"results/antenna/{t}.csv" for t in DOCUMENTS["antenna"]["tables"]},
    output={
        f: report(
            f"results/antenna/figures/{f}.png",
            category="Tracking antenna",
            subcategory="Figures",
            labels={"figure": f},
        )
        for f in REPORT_CONTENT["antenna"]["figures"]
    },
    log="antenna/figures",
    params={"dpi": config["figure_dpi"]},
)
