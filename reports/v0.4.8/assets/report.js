/* abglib reports: sortable, filterable tables (no dependencies, no network). */
(function () {
  "use strict";
  function text(cell) { return cell ? cell.textContent.trim() : ""; }
  function num(s) { var x = parseFloat(s.replace(/[<>≤≥]/g, "")); return isNaN(x) ? null : x; }

  function sortable(table) {
    var heads = table.tHead ? table.tHead.rows[0].cells : [];
    Array.prototype.forEach.call(heads, function (th, col) {
      th.setAttribute("title", "sort by this column");
      th.addEventListener("click", function () {
        var asc = th.getAttribute("aria-sort") !== "ascending";
        Array.prototype.forEach.call(heads, function (h) { h.removeAttribute("aria-sort"); });
        th.setAttribute("aria-sort", asc ? "ascending" : "descending");
        var body = table.tBodies[0];
        var rows = Array.prototype.slice.call(body.rows);
        var plain = rows.filter(function (r) { return !r.classList.contains("group"); });
        var groups = rows.filter(function (r) { return r.classList.contains("group"); });
        plain.sort(function (a, b) {
          var x = text(a.cells[col]), y = text(b.cells[col]);
          var nx = num(x), ny = num(y), c;
          if (nx !== null && ny !== null) { c = nx - ny; } else { c = x.localeCompare(y); }
          return asc ? c : -c;
        });
        plain.concat(groups).forEach(function (r) { body.appendChild(r); });
      });
    });
  }

  function filterable(table) {
    var wanted = (table.getAttribute("data-filters") || "").split(" ").filter(Boolean);
    if (!wanted.length) { return; }
    var rows = Array.prototype.slice.call(table.tBodies[0].rows);
    if (rows.length < 6) { return; }
    var tools = document.createElement("div");
    tools.className = "table-tools";
    var selects = {};
    var attrs = { verdict: "data-verdict", item: "data-section", robust: "data-robust" };
    var labels = { verdict: "verdict", item: "section", robust: "robust" };
    wanted.forEach(function (key) {
      var seen = {};
      rows.forEach(function (r) {
        (r.getAttribute(attrs[key]) || "").split(key === "item" ? "|" : " ").forEach(function (v) {
          if (v) { seen[v] = true; }
        });
      });
      var values = Object.keys(seen).sort();
      if (values.length < 2) { return; }
      var label = document.createElement("label");
      label.textContent = labels[key] + " ";
      var sel = document.createElement("select");
      sel.appendChild(new Option("all", ""));
      values.forEach(function (v) { sel.appendChild(new Option(v, v)); });
      sel.addEventListener("change", apply);
      label.appendChild(sel);
      tools.appendChild(label);
      selects[key] = sel;
    });
    var search = document.createElement("input");
    search.type = "search"; search.placeholder = "find in rows";
    search.addEventListener("input", apply);
    tools.appendChild(search);
    var count = document.createElement("span");
    count.className = "count";
    tools.appendChild(count);
    var scroller = table.parentNode;
    scroller.parentNode.insertBefore(tools, scroller);

    function apply() {
      var q = search.value.toLowerCase(), shown = 0;
      rows.forEach(function (r) {
        var ok = Object.keys(selects).every(function (key) {
          var v = selects[key].value;
          if (!v) { return true; }
          var have = (r.getAttribute(attrs[key]) || "").split(key === "item" ? "|" : " ");
          return have.indexOf(v) >= 0;
        });
        if (ok && q) { ok = r.textContent.toLowerCase().indexOf(q) >= 0; }
        r.hidden = !ok;
        if (ok) { shown += r.classList.contains("group") ? r.querySelectorAll("table.inner tbody tr").length : 1; }
      });
      count.textContent = shown + " rows shown";
    }
    apply();
  }

  document.addEventListener("DOMContentLoaded", function () {
    Array.prototype.forEach.call(document.querySelectorAll("table.data:not(.inner)"), function (t) {
      sortable(t);
      filterable(t);
    });
  });
})();
