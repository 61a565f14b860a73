# Every rule that runs a script of workflow/scripts (declared with script_rule, common.smk,
# in the other rule files): one definition. The script runs through run_script (common.smk:
# the warm worker in a local build, in place in a cluster job's own process), under the
# one conda environment. Included last, once every declaration is in.

for name, job in SCRIPT_RULES.items():

    rule:
        name:
            name
        input:
            **job["input"],
        output:
            **job["output"],
        log:
            **job["log"],
        priority: job["priority"]
        conda:
            "../envs/abglib.yaml"
        threads: job["threads"]
        resources:
            **job["resources"],
        params:
            **job["params"],
        run:
            run_script(input, output, params, wildcards, threads, resources, log, rule)
